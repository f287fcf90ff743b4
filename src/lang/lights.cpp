// light_source { position [,] [colour] items }: point lights, spotlights and
// area lights, drt's radiometric `inverse_square` and its area sampling
// methods. The dialects differ in the area-light default: .drt lights
// illuminate fully from stratified points (Cook); POV-Ray's average only the
// shadow over an edge-to-edge grid, and do not dim through media.
#include "lang/evaluator.h"

#include <cmath>
#include <fmt/format.h>

namespace drt::lang {

using Kind = Value::Kind;

Light Evaluator::lightSource(SourceLoc loc, std::optional<ObjectValue>* looksLike) {
    expectSymbol("{", "after 'light_source'");
    BlockScope scope(*this, "light_source", loc);
    Light l;
    l.loc = loc;
    l.mediaAttenuation = scene().mediaAttenuationDefault;
    l.areaIllumination = scene().fullAreaLights;
    AreaLight area; // area-light modifiers may come before area_light (POV-Ray keeps them as flags)
    // POV-Ray's dialect: its grid points, shared out over the pixel's samples (render/lighting.h),
    // which converges to POV-Ray's weighted sum over the grid.
    area.sampling = scene().fullAreaLights ? AreaSampling::Stratified : AreaSampling::Grid;
    bool hasArea = false;
    SourceLoc pointAtLoc;
    MotionChain motion; // the light's motions and the transforms after them
    std::optional<ObjectValue> projected; // projected_through's object
    SourceLoc projectedLoc;
    const Token first = peek();
    const Cell id = first.kind == TokenKind::Word ? use(first.text) : nullptr;
    if (id && id->kind == Kind::Object && id->object->lights.size() == 1 && (id->object->lightOnly || looksLike)) {
        // A declared light; one with looks_like is its shape carrying the light.
        next();
        l = id->object->lights.front();
        if (l.area) area = *l.area, hasArea = true;
        if (l.motion) motion = l.motion->chain;
        if (!id->object->lightOnly) {
            *looksLike = *id->object;
            (*looksLike)->lights.clear();
        }
    } else {
        l.position = vectorExpr("the light position <x, y, z>");
        acceptSymbol(",");
    }
    for (;;) {
        const Token t = peek();
        if (t.is("}")) {
            next();
            break;
        }
        // After a motion, a transform goes after it: the light's motion chain
        // moves it at each ray's time (render/light_path.h).
        // A looks_like object moves with the light.
        if (t.isWord("motion")) {
            if (projected || l.projectedThrough)
                fail(t.loc, "'motion' in a light with 'projected_through': a moving light cannot shine through an object");
            next();
            motion.push_back(MotionStage{motionBlock(), Transform()});
            if (looksLike && *looksLike) (*looksLike)->object.motion.push_back(motion.back());
            continue;
        }
        if (std::optional<Transform> tr = transformItem(); tr && !motion.empty()) {
            if (looksLike && *looksLike) applyTransform(**looksLike, *tr, t.loc);
            motion.back().after = motion.back().after.then(*tr);
            continue;
        } else if (tr) {
            if (looksLike && *looksLike) applyTransform(**looksLike, *tr, t.loc);
            if (projected) applyTransform(*projected, *tr, t.loc);
            transformProjectedThrough(l, *tr); // a declared light's
            l.position = tr->point(l.position);
            l.pointAt = tr->point(l.pointAt);
            area.axis1 = tr->vector(area.axis1);
            area.axis2 = tr->vector(area.axis2);
            continue;
        }
        if (startsColor(t) && !t.is("(") && !t.is("-") && !t.isWord("filter")) {
            l.color = rgbExpr();
            continue;
        }
        next();
        if (t.kind != TokenKind::Word) failInBlock(t, "a light_source keyword or '}'");
        const std::string& w = t.text;
        const SourceLoc at = peek().loc;
        auto nonNegative = [&](double& target) {
            target = floatExpr();
            if (target < 0) refuse(at, "'" + w + "' must not be negative" + got(target));
        };
        if (w == "spotlight") l.spotlight = true;
        else if (w == "point_at") pointAtLoc = at, l.pointAt = vectorExpr();
        // Used through their cosines, as POV-Ray does, so cones wider than 90 degrees work (lights/laser.pov).
        else if (w == "radius") nonNegative(l.radius);
        else if (w == "falloff") nonNegative(l.falloff);
        else if (w == "tightness") nonNegative(l.tightness);
        else if (w == "fade_distance") nonNegative(l.fadeDistance);
        else if (w == "fade_power") nonNegative(l.fadePower);
        else if (w == "shadowless") l.shadowless = true;
        else if (w == "area_light") {
            hasArea = true;
            area.axis1 = vectorExpr();
            requireNonZero(area.axis1, at, "area_light axis");
            if (syntax().requireCommas) expectSymbol(",", "after the first area_light axis");
            else acceptSymbol(",");
            const SourceLoc axis2Loc = peek().loc;
            area.axis2 = vectorExpr();
            requireNonZero(area.axis2, axis2Loc, "area_light axis");
            if (syntax().requireCommas) expectSymbol(",", "after the second area_light axis");
            else acceptSymbol(",");
            const SourceLoc n1Loc = peek().loc;
            // A size below 1 is reported as such; one past the limit (or not
            // finite) before it becomes an int.
            const double most = double(diags_.limits().areaLightSamples);
            const auto size = [&](SourceLoc loc) {
                const double n = floatExpr("the area_light size");
                if (std::isfinite(n) && n != std::floor(n) && syntax().strictValues)
                    error(loc, "the area_light size must be a whole number");
                if (n < 1 && n > -most) return int(n);
                return countValue(n, loc, "area_light size", 1, most);
            };
            area.size1 = size(n1Loc);
            if (syntax().requireCommas) expectSymbol(",", "after the first area_light size");
            else acceptSymbol(",");
            const SourceLoc n2Loc = peek().loc;
            area.size2 = size(n2Loc);
            if (area.size1 < 1) error(n1Loc, "area_light sizes must be at least 1" + got(area.size1));
            if (area.size2 < 1) error(n2Loc, "area_light sizes must be at least 1" + got(area.size2));
            if (const double samples = double(area.size1) * double(area.size2); samples > most)
                error(n1Loc, limitExceeded(diags_.limits(), &Limits::areaLightSamples,
                                           fmt::format("the area_light's sample count {} x {} =", area.size1,
                                                       area.size2),
                                           samples));
            area.size1 = std::max(area.size1, 1);
            area.size2 = std::max(area.size2, 1);
        } else if (w == "jitter") area.jitter = optionalBool(true);
        else if (w == "adaptive") {
            area.adaptive = countExpr("area_light adaptive", -1e9, 1e9);
            if (area.adaptive < 0) refuse(at, "'adaptive' must not be negative" + got(area.adaptive));
        } else if (w == "circular") area.circular = optionalBool(true);
        else if (w == "orient") area.orient = optionalBool(true);
        else if (w == "area_illumination") l.areaIllumination = optionalBool(true);
        else if (w == "inverse_square") l.inverseSquare = optionalBool(true);
        else if (w == "media_interaction") l.mediaInteraction = optionalBool(true);
        else if (w == "media_attenuation") l.mediaAttenuation = optionalBool(true);
        else if (w == "area_sampling") {
            const Token name = next();
            bool found = false;
            for (const AreaSamplingWord& s : areaSamplingWords())
                if (name.isWord(s.word)) area.sampling = s.sampling, found = true;
            if (!found) failExpected(name, "'stratified', 'solid_angle', 'grid' or 'pov_grid' after 'area_sampling'");
        } else if (w == "looks_like" && looksLike && !motion.empty()) {
            fail(t.loc, "'looks_like' after 'motion': give the light's shape before its motion");
        } else if (w == "looks_like" && looksLike) {
            // POV-Ray: the object is moved to the light's position, moves with
            // the light's later transforms and casts no shadow.
            if (*looksLike) fail(t.loc, "only one looks_like is allowed per light_source");
            ObjectValue shape = object(Token{TokenKind::Word, "object", 0, t.loc}); // reads `{ object modifiers }`
            applyTransform(shape, Transform::translate(l.position), t.loc);
            shape.object.noShadow = true;
            *looksLike = std::move(shape);
        } else if (w == "projected_through") {
            // POV-Ray: the light shines only through the object, which is
            // never drawn and moves with the light's later transforms.
            if (projected || l.projectedThrough) fail(t.loc, "only one projected_through is allowed per light_source");
            if (!motion.empty())
                fail(t.loc, "'projected_through' after 'motion': a moving light cannot shine through an object");
            projected = object(Token{TokenKind::Word, "object", 0, t.loc}); // reads `{ object modifiers }`
            projectedLoc = t.loc;
        } else if (w == "looks_like" || w == "photons") {
            unsupported("light-" + w, t.loc, "light_source '" + w + "' is not supported and is ignored");
            expectSymbol("{", "after '", w, "'");
            skipBlock();
        } else if (w == "parallel") {
            l.parallel = true;
        } else if (w == "cylinder") {
            unsupported("light-" + w, t.loc, "'" + w + "' lights are not supported; treated as a point light");
        } else {
            failUnknown(t, Block::LightSource);
        }
    }
    if (l.spotlight && l.pointAt == l.position)
        refuse(pointAtLoc.valid() ? pointAtLoc : loc, "'point_at' is the same point as the light position");
    if (hasArea) l.area = area;
    if (projected) {
        if (projected->lightOnly) fail(projectedLoc, "'projected_through' needs an object with a shape");
        auto through = std::make_shared<Scene>();
        through->objects.push_back(placed(std::move(*projected)));
        l.projectedThrough = std::move(through);
    }
    if (!motion.empty()) l.motion = std::make_shared<LightMotion>(LightMotion{{}, std::move(motion)});
    return l;
}

} // namespace drt::lang
