// The .drt text of the algebraic shapes (see parser_algebraic.cpp), with every
// coefficient written so that it reads back exactly.
#include "lang/writer_detail.h"

namespace drt::writer {

std::string algebraicHead(const Algebraic& a) {
    std::vector<double> c = a.coefficients;
    if (a.form == Algebraic::Form::Quadric) {
        c.resize(10, 0.0); // both parsers give a quadric 10 coefficients
        return "quadric { " + vector({c[0], c[1], c[2]}) + ", " + vector({c[3], c[4], c[5]}) + ", " +
               vector({c[6], c[7], c[8]}) + ", " + number(c[9]);
    }
    std::string text;
    switch (a.form) {
    case Algebraic::Form::Cubic: text = "cubic { <"; break;
    case Algebraic::Form::Quartic: text = "quartic { <"; break;
    default: text = "poly { " + std::to_string(a.order) + ", <"; break;
    }
    for (size_t i = 0; i < c.size(); ++i) text += (i ? ", " : "") + number(c[i]);
    return text + ">" + (a.sturm ? " sturm" : "");
}

std::string superellipsoidHead(const Superellipsoid& s) {
    return "superellipsoid { <" + number(s.e) + ", " + number(s.n) + ">";
}

} // namespace drt::writer
