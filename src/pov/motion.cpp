// drt's `motion { ... }` in the POV-Ray dialect (an extension: POV-Ray has no
// motion blur): the same block as in .drt (grammar/drt.ebnf motion), on
// objects, cameras and lights, standing where it is written among the
// transforms (scene/motion.h).
#include "pov/parser.h"

namespace drt::pov {

// motion = "motion" "{" [ "spline" ] ( key_items | { "at" float key_items } ) "}"
Motion PovParser::motionBlock() {
    expectSymbol("{", "after 'motion'");
    Motion m;
    bool keyed = false;
    bool seen[3] = {false, false, false};
    for (;;) {
        const Tok t = next();
        if (t.is("}")) break;
        if (t.kind != TokKind::Word) failExpected(t, "'at', 'translate', 'rotate', 'scale', 'spline' or '}' in motion");
        if (t.text == "spline") {
            if (m.spline) fail(t.loc, "'spline' given twice in motion");
            m.spline = true;
            continue;
        }
        if (t.text == "at") {
            if (!keyed && !m.keys.empty()) fail(t.loc, "'at' after key items without a time; begin with 'at'");
            keyed = true;
            const SourceLoc loc = peek().loc;
            const double time = floatExpr();
            if (!(time >= 0 && time <= 1)) fail(loc, "motion key times must be in [0, 1]");
            if (!m.keys.empty() && !(time > m.keys.back().time)) fail(loc, "motion key times must increase");
            m.keys.push_back(MotionKey{time});
            seen[0] = seen[1] = seen[2] = false;
            continue;
        }
        const int index = t.text == "translate" ? 0 : t.text == "rotate" ? 1 : t.text == "scale" ? 2 : -1;
        if (index < 0) failExpected(t, "'at', 'translate', 'rotate', 'scale', 'spline' or '}' in motion");
        if (m.keys.empty()) m.keys.push_back(MotionKey{1});
        if (seen[index]) fail(t.loc, "'" + t.text + "' given twice in " + (keyed ? "one motion key" : "motion"));
        seen[index] = true;
        const SourceLoc loc = peek().loc;
        const Vec3 v = vectorExpr();
        MotionKey& key = m.keys.back();
        if (index == 0) key.translate = v;
        else if (index == 1) key.rotate = v;
        else if (v.x == 0 || v.y == 0 || v.z == 0) fail(loc, "motion scale has a zero component");
        else key.scale = v;
    }
    if (m.keys.empty()) m.keys.push_back(MotionKey{1});
    if (m.keys.front().time > 0) m.keys.insert(m.keys.begin(), MotionKey{0});
    return m;
}

} // namespace drt::pov
