sphere { 0, 1 pigment { checker scale 1e-20 } }
#declare A = array[2];
#declare B = A[1e10];
