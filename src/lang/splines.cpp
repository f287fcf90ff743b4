// spline { [identifier] [kind] t, value ... }: POV-Ray's spline values, called
// like functions (S(t), S(t, kind)) as the scene is read and, wrapped as
// `function { spline { ... } }`, inside functions (F(x).y).
#include "lang/evaluator.h"
#include "lang/mesh_syntax.h"

#include <fmt/format.h>

namespace drt::lang {

using Kind = Value::Kind;

namespace {

std::optional<Spline::Kind> splineKindNamed(const std::string& word) {
    for (const Spline::Kind k : {Spline::Kind::Linear, Spline::Kind::Quadratic, Spline::Kind::Cubic, Spline::Kind::Natural})
        if (word == splineKindWord(k)) return k;
    return std::nullopt;
}

} // namespace

std::shared_ptr<const Spline> Evaluator::splineBlock(SourceLoc keyword) {
    expectSymbol("{", "after 'spline'");
    BlockScope scope(*this, "spline", keyword);
    auto s = std::make_shared<Spline>();
    std::vector<Spline::Entry> added; // inserted at the end, in one go
    bool first = true;
    for (;;) {
        const Token t = peek();
        if (t.is("}")) {
            next();
            break;
        }
        if (t.kind == TokenKind::Word) {
            if (const auto k = splineKindNamed(t.text)) {
                next();
                s->kind = *k;
                first = false;
                continue;
            }
            if (first) {
                if (const Cell c = lookup(t.text); c && c->kind == Kind::Spline) {
                    next();
                    use(t.text);
                    *s = *c->spline;
                    first = false;
                    continue;
                }
            }
        }
        first = false;
        const SourceLoc at = t.loc;
        double time;
        {
            FlagFor flag(countBeforeVector_); // `0 <1, 2, 3>`: '<' starts the value, not a comparison
            time = floatExpr("the entry's parameter");
        }
        if (syntax().requireCommas) expectSymbol(",", "between the entry's parameter and its value");
        else acceptSymbol(",");
        const SourceLoc valueLoc = peek().loc;
        const Value v = expression();
        std::array<double, 5> values{};
        int terms = 1;
        if (v.kind == Kind::Float) {
            values.fill(v.number);
        } else if (v.kind == Kind::Vector || v.kind == Kind::Color) {
            values = v.v;
            terms = v.size;
        } else {
            fail(valueLoc, "a spline entry's value must be a number or a vector, not " + kindName(v));
        }
        if (!std::isfinite(time)) fail(at, "a spline entry's parameter must be finite" + got(time));
        added.push_back({time, values});
        s->terms = std::max(s->terms, terms);
        acceptSymbol(",");
    }
    s->insert(std::move(added));
    if (s->entries.empty()) fail(keyword, "spline has no entries");
    return s;
}

Value Evaluator::callSpline(const Token& name, const Spline& s) {
    expectSymbol("(", "after the spline '", name.text, "'");
    const bool saved = inVector_;
    inVector_ = false;
    const double t = floatExpr("the spline's parameter");
    Spline::Kind kind = s.kind;
    if (acceptSymbol(",")) {
        const Token k = expectWord("a spline kind (linear_spline, quadratic_spline, cubic_spline or natural_spline)");
        const auto named = splineKindNamed(k.text);
        if (!named)
            failUnknownIn(k, {"linear_spline", "quadratic_spline", "cubic_spline", "natural_spline"}, "spline kind");
        kind = *named;
    }
    inVector_ = saved;
    expectSymbol(")", "to close the spline's parameter");
    Value v;
    v.kind = Kind::Vector;
    v.size = s.terms;
    v.v = s.at(t, kind);
    return v;
}

} // namespace drt::lang
