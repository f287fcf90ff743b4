// The two dialects of drt's scene language. Both run on one lexer and one
// evaluator (lang/evaluator.h) and build the one scene model; a dialect is the
// small table of what differs between them: defaults, the POV-Ray legacy rules
// that apply, and how strictly input is checked. Every drt extension (motion,
// reflection_blur, refraction_blur, the render block, area_sampling,
// inverse_square, ...) and every directive works in both. docs/language.md
// and docs/pov.md describe the differences for users.
#pragma once

#include <optional>
#include <string>

namespace drt {

enum class DialectKind { Drt, Pov };

struct Dialect {
    DialectKind kind = DialectKind::Drt;
    const char* name = "drt"; // for messages: "drt", "pov"

    // ---- checking
    // Malformed numbers (`12ab`, `1e+`) and unknown string escapes are errors
    // (POV-Ray reads `12ab` as a number and a word and keeps an unknown escape's character).
    bool strictLexing = true;
    // Commas between a shape's or vector's arguments are required, and a
    // #declare of a number or vector needs its ';'. POV-Ray lets both out.
    bool requireCommas = true;
    // Every error is reported, the evaluator skipping to the next statement
    // after each; otherwise the first error stops (as POV-Ray does).
    bool recoverAfterErrors = true;
    // Values POV-Ray accepts but drt's rules refuse (a negative diffuse, a
    // zero-length axis, ...) are errors; otherwise they are kept as POV-Ray keeps them.
    bool strictValues = true;
    // A construct drt does not support (isosurface, photons, ...) is an error;
    // otherwise it is left out with a warning saying so.
    bool unsupportedIsError = true;

    // ---- defaults
    // The camera's `right` is the image aspect unless given (POV-Ray: <1.33, 0, 0>).
    bool rightFromImageAspect = true;
    // Area lights illuminate fully from stratified points (Cook); otherwise
    // POV-Ray's edge-to-edge grid that averages only the shadow.
    bool fullAreaLights = true;
    // Media along a light's path dim it (POV-Ray's media_attenuation default is off).
    bool mediaAttenuationDefault = true;
    // A pattern without a colour_map gets the grey ramp, and checker/hexagon/brick
    // their list colours, as the .drt documentation gives them.
    bool drtPatternDefaults = true;

    // A block given to something that already has one (`finish { }` in a
    // texture with a finish, a second `camera { }`) starts from it, as in
    // POV-Ray; otherwise from the defaults.
    bool modifyBlocks = false;

    // ---- POV-Ray legacy rules
    // assumed_gamma / #version decide the working gamma; srgb colours and
    // image maps are encoded in it (otherwise colours are linear and
    // assumed_gamma is kept as given).
    bool versionGammaRules = false;
    // The camera's vectors are resolved as POV-Ray's parser does (angle,
    // look_at and transforms applied in order), and its right defaults to <1.33, 0, 0>.
    bool povCameraRules = false;
    // A union stays one CSG object in the model (the .drt dialect flattens it into its members).
    bool keepUnions = false;
    // A number right before a vector in a list (`4 <1, 2>`) is a count, and
    // `finish { ior ... }` is POV-Ray 3.1 syntax that is ignored with a warning.
    bool legacySyntax = false;
};

const Dialect& drtDialect();
const Dialect& povDialect();

// The dialect named by `name` ("drt" or "pov"), or nothing.
std::optional<DialectKind> dialectNamed(const std::string& name);
const Dialect& dialectOf(DialectKind kind);

// The dialect a file's extension selects: .pov, .inc and .mac are POV-Ray
// scenes, everything else .drt.
DialectKind dialectForPath(const std::string& path);

} // namespace drt
