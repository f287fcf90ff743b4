camera { cylinder 1e10 }
