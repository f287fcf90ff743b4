// Every error the .drt parser can report, with its message, line and column.
// Each case is a tiny scene whose first error is the one under test.
#include "lang/load.h"
#include "test_support.h"

#include <gtest/gtest.h>

namespace drt {
namespace {

struct ErrorCase {
    const char* name;
    const char* source;
    const char* message;
    int line, column;
};

std::ostream& operator<<(std::ostream& os, const ErrorCase& c) { return os << c.name; }

class ParserErrors : public testing::TestWithParam<ErrorCase> {};

TEST_P(ParserErrors, MessageAndLocation) {
    const ErrorCase& c = GetParam();
    Diagnostics diags;
    const auto scene = loadSceneText(c.source, "e.drt", diags);
    EXPECT_FALSE(scene);
    ASSERT_GE(diags.errorCount(), 1);
    const Diagnostic& d = diags.all()[0];
    EXPECT_EQ(d.message, c.message);
    EXPECT_EQ(d.loc.line, c.line);
    EXPECT_EQ(d.loc.column, c.column);
    EXPECT_EQ(d.severity, Severity::Error);
}

// clang-format off
const ErrorCase kCases[] = {
    // lexical errors reach the diagnostics with their location
    {"LexicalError", "sphere { 0, 1 @ }", "unexpected character '@'", 1, 15},
    // statements and directives
    {"UnknownKeyword", "sphear { 0, 1 }", "unknown keyword 'sphear'; did you mean 'sphere'?", 1, 1},
    {"UnknownKeywordNoSuggestion", "qqqqqqqq", "unknown keyword 'qqqqqqqq'", 1, 1},
    {"UnknownDirective", "#delcare A = 1;", "unknown directive '#delcare'; did you mean '#declare'?", 1, 1},
    {"NotAStatement", "#declare A = 1;\nA", "'A' is a number, not a statement", 2, 1},
    {"ObjectNameAsStatement", "#declare B = sphere { 0, 1 }\nB", "'B' is an object, not a statement; write object { B }", 2, 1},
    {"StatementExpected", "{", "expected a statement (an object, camera, light_source, ...), found '{'", 1, 1},
    {"DeclareKeyword", "#declare sphere = 1;", "cannot declare 'sphere': it is a keyword", 1, 10},
    {"DeclareNeedsName", "#declare = 1;", "expected a name after '#declare', found '='", 1, 10},
    {"DeclareNeedsEquals", "#declare A 1;", "expected '=' after the declared name, found '1'", 1, 12},
    {"DeclareNeedsSemicolon", "#declare A = 1\nsphere { 0, A }", "expected ';' after the value of 'A'", 1, 14},
    {"IncludeNeedsString", "#include foo", "expected a file name in quotes after '#include', found 'foo'", 1, 10},
    {"IncludeMissing", "#include \"no/such.drt\"", "cannot find include file 'no/such.drt' (looked for no/such.drt, /usr/share/povray-3.7/include/no/such.drt)", 1, 10},
    {"MissingBrace", "sphere 0, 1 }", "expected '{' after 'sphere', found '0'", 1, 8},
    {"UnclosedBlock", "sphere { 0, 1", "expected an object modifier or '}' to close 'sphere', found end of file", 1, 14},
    // expressions
    {"UnknownIdentifier", "#declare Radius = 1;\nsphere { 0, Radus }", "unknown identifier 'Radus'; did you mean 'Radius'?", 2, 13},
    {"ValueExpected", "sphere { 0, * }", "expected a value (a number, a vector <x, y, z> or a name), found '*'", 1, 13},
    {"UnclosedParen", "sphere { 0, (1 }", "expected ')' to close '(', found '}'", 1, 16},
    {"DivisionByZero", "sphere { 0, 1 / 0 }", "division by zero", 1, 15},
    {"VectorDivisionByZero", "sphere { <1, 1, 1> / <1, 0, 1>, 1 }", "division by zero", 1, 20},
    {"ProductOverflow", "sphere { 0, 1e300 * 1e300 }", "result of '*' is not a finite number", 1, 19},
    {"SumOverflow", "sphere { 0, 1e308 + 1e308 }", "result of '+' is not a finite number", 1, 19},
    {"SqrtOfNegative", "sphere { 0, sqrt(-1) }", "result of 'sqrt' is not a finite number (argument out of its domain)", 1, 13},
    {"LogOfZero", "sphere { 0, log(0) }", "result of 'log' is not a finite number (argument out of its domain)", 1, 13},
    {"ModByZero", "sphere { 0, mod(1, 0) }", "result of 'mod' is not a finite number (argument out of its domain)", 1, 13},
    {"NormalizeZero", "sphere { vnormalize(0), 1 }", "'vnormalize' of a zero-length vector", 1, 10},
    {"WrongArity", "sphere { 0, pow(2) }", "'pow' takes 2 arguments, got 1", 1, 13},
    {"WrongArityOne", "sphere { 0, sin(1, 2) }", "'sin' takes 1 argument, got 2", 1, 13},
    {"MinNeedsTwo", "sphere { 0, min(1) }", "'min' takes at least 2 arguments, got 1", 1, 13},
    {"FunctionNeedsParen", "sphere { 0, sqrt 4 }", "expected '(' after 'sqrt', found '4'", 1, 18},
    {"FunctionArgumentKind", "sphere { 0, sqrt(<1, 2, 3>) }", "argument of 'sqrt' must be a number, not a vector", 1, 18},
    {"VectorFunctionArgumentKind", "#declare T = texture { }\nsphere { 0, vlength(T) }", "argument of 'vlength' must be a number, not a texture", 2, 21},
    {"AddTexture", "#declare T = texture { }\nsphere { 0, T + 1 }", "cannot apply '+' to a texture", 2, 15},
    {"MultiplyPigment", "#declare P = pigment { }\nsphere { 0, 2 * P }", "cannot apply '*' to a pigment", 2, 15},
    {"NegateFinish", "#declare F = finish { }\nsphere { 0, -F }", "cannot apply unary '-' to a finish", 2, 13},
    {"VectorComponentKind", "sphere { <1, <1, 2>, 3>, 1 }", "a vector component must be a number, not a vector", 1, 14},
    {"VectorTooLong", "sphere { <1, 2, 3, 4, 5, 6>, 1 }", "a vector has at most 5 components", 1, 26},
    {"VectorTooShort", "sphere { <1>, 1 }", "a vector needs 2 to 5 components, got 1", 1, 10},
    {"VectorUnclosed", "sphere { <1, 2 3>, 1 }", "expected ',' or '>' in the vector, found '3'", 1, 16},
    {"FloatExpected", "sphere { 0, <1, 2, 3> }", "expected sphere radius, found a vector", 1, 13},
    {"VectorExpected", "#declare T = texture { }\nsphere { T, 1 }", "expected the centre <x, y, z>, found a texture", 2, 10},
    {"ColourExpected", "#declare F = finish { }\nbackground { F }", "expected a colour, found a finish", 2, 14},
    {"ColourAfterColourKeyword", "#declare F = finish { }\nbackground { color F }", "expected a colour, found a finish", 2, 20},
    {"RgbfNeedsFour", "background { rgbf <1, 2, 3> }", "'rgbf' needs 4 components, got 3", 1, 19},
    {"RgbNeedsNumber", "#declare F = finish { }\nbackground { rgb F }", "'rgb' needs a number or a vector, not a finish", 2, 18},
    {"WholeNumber", "global_settings { max_trace_level 2.5 }", "'max_trace_level' must be a whole number", 1, 35},
    // transforms
    {"ZeroScale", "sphere { 0, 1 scale <1, 0, 1> }", "scale has a zero component (the object would collapse), got <1, 0, 1>", 1, 21},
    {"MatrixTooLong", "sphere { 0, 1 matrix <1,0,0,0,1,0,0,0,1,0,0,0,5> }", "'matrix' takes exactly 12 numbers", 1, 47},
    {"MatrixTooShort", "sphere { 0, 1 matrix <1, 0, 0> }", "'matrix' takes exactly 12 numbers, got 3", 1, 15},
    {"MatrixNeedsAngle", "sphere { 0, 1 matrix 1 }", "expected '<' after 'matrix', found '1'", 1, 22},
    {"SingularMatrix", "sphere { 0, 1 matrix <1,0,0, 0,0,0, 0,0,1, 0,0,0> }", "singular matrix (it has no inverse)", 1, 15},
    // camera
    {"CameraUnknown", "camera { loction 0 }", "unknown keyword 'loction'; did you mean 'location'?", 1, 10},
    {"CameraNotWord", "camera { 1 }", "expected a camera keyword or '}', found '1'", 1, 10},
    {"LookAtIsLocation", "camera { location <1, 2, 3>\n look_at <1, 2, 3> }", "'look_at' is the same point as 'location'", 2, 10},
    {"FocalPointIsLocation", "camera { focal_point 0 }", "'focal_point' is the same point as 'location'", 1, 22},
    {"ZeroUp", "camera { up 0 }", "'up' must not be a zero-length vector", 1, 13},
    {"ZeroSky", "camera { sky <0, 0, 0> }", "'sky' must not be a zero-length vector", 1, 14},
    {"ZeroRight", "camera { right 0 }", "'right' must not be a zero-length vector", 1, 16},
    {"ZeroDirection", "camera { direction 0 }", "'direction' must not be a zero-length vector", 1, 20},
    {"AngleRange", "camera { angle 180 }", "'angle' must be between 0 and 180 degrees, got 180", 1, 16},
    {"NegativeAperture", "camera { aperture -1 }", "'aperture' must not be negative, got -1", 1, 19},
    {"FocalDistance", "camera { focal_distance 0 }", "'focal_distance' must be positive, got 0", 1, 25},
    {"ShutterOrder", "camera { shutter_open 1 shutter_close 0.5 }", "'shutter_close' is before 'shutter_open'", 1, 39},
    // light_source
    {"LightUnknown", "light_source { 0, rgb 1 spotligt }", "unknown keyword 'spotligt'; did you mean 'spotlight'?", 1, 25},
    {"LightNotWord", "light_source { 0, rgb 1 { }", "expected a light_source keyword or '}', found '{'", 1, 25},
    {"LightNeedsPosition", "#declare T = texture { }\nlight_source { T }", "expected the light position <x, y, z>, found a texture", 2, 16},
    {"SpotRadius", "light_source { 0 radius -5 }", "'radius' must not be negative, got -5", 1, 25},
    {"SpotFalloff", "light_source { 0 falloff -1 }", "'falloff' must not be negative, got -1", 1, 26},
    {"Tightness", "light_source { 0 tightness -1 }", "'tightness' must not be negative, got -1", 1, 28},
    {"LightFadeDistance", "light_source { 0 fade_distance -1 }", "'fade_distance' must not be negative, got -1", 1, 32},
    {"LightFadePower", "light_source { 0 fade_power -1 }", "'fade_power' must not be negative, got -1", 1, 29},
    {"PointAtIsPosition", "light_source { y spotlight point_at y }", "'point_at' is the same point as the light position", 1, 37},
    {"AreaAxisZero", "light_source { 0 area_light 0, z, 2, 2 }", "area_light axis must not be a zero-length vector", 1, 29},
    {"AreaSecondAxisZero", "light_source { 0 area_light x, 0, 2, 2 }", "area_light axis must not be a zero-length vector", 1, 32},
    {"AreaSize", "light_source { 0 area_light x, z, 0, 2 }", "area_light sizes must be at least 1, got 0", 1, 35},
    {"AreaSecondSize", "light_source { 0 area_light x, z, 2, -1 }", "area_light sizes must be at least 1, got -1", 1, 38},
    {"AreaComma", "light_source { 0 area_light x z }", "expected ',' after the first area_light axis, found 'z'", 1, 31},
    {"Adaptive", "light_source { 0 adaptive -1 }", "'adaptive' must not be negative, got -1", 1, 27},
    // background, global_settings, render
    {"BackgroundUnclosed", "background { rgb 1 rgb 0", "expected '}' after the background colour, found end of file", 1, 25},
    {"GlobalUnknown", "global_settings { max_trace 3 }", "unknown keyword 'max_trace'; did you mean 'max_trace_level'?", 1, 19},
    {"GlobalNotWord", "global_settings { 3 }", "expected a global_settings keyword or '}', found '3'", 1, 19},
    {"MaxTraceLevel", "global_settings { max_trace_level 0 }", "'max_trace_level' must be at least 1, got 0", 1, 35},
    {"AssumedGamma", "global_settings { assumed_gamma 0 }", "'assumed_gamma' must be positive, got 0", 1, 33},
    {"AdcBailout", "global_settings { adc_bailout -1 }", "'adc_bailout' must not be negative, got -1", 1, 31},
    {"RenderWidth", "render { width 0 }", "'width' must be at least 1, got 0", 1, 16},
    {"RenderHeight", "render { height -2 }", "'height' must be at least 1, got -2", 1, 17},
    {"RenderSamples", "render { samples 0 }", "'samples' must be at least 1, got 0", 1, 18},
    {"RenderSeed", "render { seed -1 }", "'seed' must be a whole number >= 0, got -1", 1, 15},
    {"RenderSampler", "render { sampler \"independant\" }", "unknown sampler 'independant'; did you mean 'independent'? (the samplers are sobol, independent, stratified)", 1, 18},
    {"RenderSamplerString", "render { sampler independent }", "expected a sampler name in quotes, found 'independent'", 1, 18},
    {"RenderFilter", "render { filter \"gausian\" }", "unknown filter 'gausian'; did you mean 'gaussian'? (the filters are box, tent, gaussian)", 1, 17},
    {"RenderFilterString", "render { filter box }", "expected a filter name in quotes, found 'box'", 1, 17},
    {"RenderUnknown", "render { widht 4 }", "unknown keyword 'widht'; did you mean 'width'?", 1, 10},
    {"RenderNotWord", "render { \"x\" }", "expected a render keyword or '}', found string \"x\"", 1, 10},
    // objects
    {"UnknownModifier", "sphere { 0, 1 tranlate x }", "unknown keyword 'tranlate'; did you mean 'translate'?", 1, 15},
    {"ModifierNotWord", "sphere { 0, 1 1 }", "expected an object modifier or '}' to close 'sphere', found '1'", 1, 15},
    {"UnknownObject", "#declare Ball = sphere { 0, 1 }\nobject { Bal }", "unknown object 'Bal'; did you mean 'Ball'?", 2, 10},
    {"NotAnObject", "#declare T = texture { }\nobject { T }", "'T' is a texture, not an object", 2, 10},
    {"SphereRadius", "sphere { 0, -1 }", "sphere radius must be positive, got -1", 1, 13},
    {"SphereComma", "sphere { 0 1 }", "expected ',' after the centre, found '1'", 1, 12},
    {"PlaneNormal", "plane { 0, 1 }", "plane normal must not be a zero-length vector", 1, 9},
    {"CylinderRadius", "cylinder { 0, y, 0 }", "cylinder radius must be positive, got 0", 1, 18},
    {"CylinderAxis", "cylinder { y, y, 1 }", "cylinder base and cap are the same point (zero-length axis)", 1, 15},
    {"ConeNegative", "cone { 0, -1, y, 1 }", "cone radius must not be negative, got -1", 1, 11},
    {"ConeNegativeCap", "cone { 0, 1, y, -1 }", "cone radius must not be negative, got -1", 1, 17},
    {"ConeBothZero", "cone { 0, 0, y, 0 }", "cone needs at least one positive radius", 1, 17},
    {"ConeAxis", "cone { x, 1, x, 0 }", "cone base and cap are the same point (zero-length axis)", 1, 14},
    {"DiscNormal", "disc { 0, 0, 1 }", "disc normal must not be a zero-length vector", 1, 11},
    {"DiscRadius", "disc { 0, y, 0 }", "disc radius must be positive, got 0", 1, 14},
    {"DiscHole", "disc { 0, y, 1, -1 }", "disc hole radius must not be negative, got -1", 1, 17},
    {"TorusMajor", "torus { 0, 1 }", "torus major radius must be positive, got 0", 1, 9},
    {"TorusMinor", "torus { 1, -0.5 }", "torus minor radius must be positive, got -0.5", 1, 12},
    {"TriangleComma", "triangle { 0, x y }", "expected ',' between triangle corners, found 'y'", 1, 17},
    {"SmoothNormal", "smooth_triangle { 0, 0, x, y, y, y }", "smooth_triangle normal must not be a zero-length vector", 1, 22},
    {"EmptyMesh", "mesh { }", "mesh has no triangles", 1, 1},
    {"MeshTriangleBrace", "mesh { triangle 0, x, y }", "expected '{' after 'triangle', found '0'", 1, 17},
    {"EmptyUnion", "union { }", "union has no objects", 1, 1},
    {"OpenOnSphere", "sphere { 0, 1 open }", "'open' applies only to cylinder, cone and prism, and to sor and isosurface", 1, 15},
    // prism and text
    {"PrismTooFewPoints", "prism { 0, 1, 2, <0, 0>, <1, 0> }", "this prism spline needs at least 3 points", 1, 15},
    {"PrismCubicTooFewPoints", "prism { cubic_spline 0, 1, 5, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0, 0> }", "this prism spline needs at least 6 points", 1, 28},
    {"PrismPointNot2D", "prism { 0, 1, 3, <0, 0>, <1, 0, 0>, <0, 1> }", "expected a prism point <x, z>, found a vector", 1, 26},
    {"PrismMissingComma", "prism { 0, 1, 3, <0, 0> <1, 0>, <0, 1> }", "expected ',' between prism points, found '<'", 1, 25},
    {"PrismEqualHeights", "prism { 1, 1, 3, <0, 0>, <1, 0>, <0, 1> }", "prism heights must differ", 1, 12},
    {"PrismConicAcrossApex", "prism { conic_sweep -1, 1, 3, <0, 0>, <1, 0>, <0, 1> }", "conic_sweep heights must not lie on both sides of the apex at 0", 1, 25},
    {"PrismUnclosedQuadratic", "prism { quadratic_spline 0, 1, 6, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0, 2>, <5, 5> }", "too few points in prism: a sub-polygon is not closed or control points are missing", 1, 1},
    {"TextMissingFont", "text { font \"no-such-font.ttf\" string \"a\" thickness 1 }", "cannot find font 'no-such-font.ttf' (looked in ., /usr/share/povray-3.7/include)", 1, 13},
    {"TextBadFont", "text { font \"/etc/hostname\" string \"a\" thickness 1 }", "cannot read font '/etc/hostname' (not a TrueType/OpenType font?)", 1, 13},
    {"TextNeedsFont", "text { string \"a\" thickness 1 }", "expected 'font' and the font file name in quotes, found 'string'", 1, 8},
    {"TextNeedsString", "text { font \"timrom.ttf\" thickness 1 }", "expected 'string' and the text in quotes, found 'thickness'", 1, 26},
    {"TextNeedsThickness", "text { font \"timrom.ttf\" string \"a\" }", "expected 'thickness' and the depth of the letters, found '}'", 1, 37},
    {"TextZeroThickness", "text { font \"timrom.ttf\" string \"a\" thickness 0 }", "text thickness must not be zero", 1, 47},
    {"OpenOnText", "text { font \"timrom.ttf\" string \"a\" thickness 1 open }", "'open' applies only to cylinder, cone and prism, and to sor and isosurface", 1, 49},
    {"MotionTwice", "sphere { 0, 1 motion { translate x translate y } }", "'translate' given twice in motion", 1, 36},
    {"MotionScaleZero", "sphere { 0, 1 motion { scale 0 } }", "motion scale has a zero component, got <0, 0, 0>", 1, 30},
    {"MotionUnknown", "sphere { 0, 1 motion { rotat y } }", "unknown keyword 'rotat'; did you mean 'rotate'?", 1, 24},
    {"MotionNotWord", "sphere { 0, 1 motion { 1 } }", "expected 'at', 'translate', 'rotate', 'scale', 'spline' or '}' in motion, found '1'", 1, 24},
    {"MotionKeyTwice", "sphere { 0, 1 motion { at 0.5 rotate y at 1 rotate y rotate x } }", "'rotate' given twice in one motion key", 1, 54},
    {"MotionKeyTimesDecrease", "sphere { 0, 1 motion { at 0.5 rotate y at 0.5 rotate x } }", "motion key times must increase", 1, 43},
    {"MotionKeyTimeRange", "sphere { 0, 1 motion { at 1.5 rotate y } }", "motion key times must be in [0, 1], got 1.5", 1, 27},
    {"MotionAtAfterItems", "sphere { 0, 1 motion { rotate y at 1 rotate x } }", "'at' after key items without a time; begin with 'at'", 1, 33},
    {"MotionSplineTwice", "sphere { 0, 1 motion { spline spline at 1 rotate y } }", "'spline' given twice in motion", 1, 31},
    {"MotionNoBrace", "sphere { 0, 1 motion rotate y }", "expected '{' after 'motion', found 'rotate'", 1, 22},
    {"ClipAfterMotion", "sphere { 0, 1 motion { rotate y } clipped_by { box { 0, 1 } } }", "clipped_by after 'motion' is not supported; put it before the motion", 1, 35},
    {"CrandNegative", "sphere { 0, 1 finish { crand -0.1 } }", "'crand' must not be negative, got -0.1", 1, 30},
    {"CylinderCameraType", "camera { cylinder 5 }", "'cylinder' camera type must be 1, 2, 3 or 4, got 5", 1, 19},
    {"VerticalAngleNotSpherical", "camera { fisheye angle 90, 45 }", "a vertical angle is only for the spherical camera", 1, 28},
    {"VerticalAngleZero", "camera { spherical angle 90, 0 }", "the vertical angle must be positive, got 0", 1, 30},
    {"MappingAngleZero", "camera { spherical angle 0 }", "'angle' must be positive, got 0", 1, 26},
    {"PerspectiveAngleAfterFisheye", "camera { angle 200 fisheye perspective }", "'angle' must be between 0 and 180 degrees, got 200", 1, 16},
    {"MappingAperture", "camera { panoramic aperture 0.5 }", "only a perspective camera has a lens: 'aperture' must be 0", 1, 29},
    {"OrthographicAperture", "camera { orthographic aperture 0.5 }", "an orthographic camera has no lens: 'aperture' must be 0", 1, 32},
    {"ClipEmpty", "sphere { 0, 1 clipped_by { } }", "'clipped_by' needs at least one object", 1, 15},
    {"ClipNotAnObject", "sphere { 0, 1 clipped_by { pigment { rgb 1 } } }", "expected an object or '}' in clipped_by, found 'pigment'", 1, 28},
    {"ClipNoBrace", "sphere { 0, 1 clipped_by box { 0, 1 } }", "expected '{' after 'clipped_by', found 'box'", 1, 26},
    {"ClipWithMotion", "sphere { 0, 1 clipped_by { box { 0, 1 motion { translate x } } } }", "'motion' on a clipped_by object is not supported", 1, 28},
    // textures
    {"TextureUnknown", "sphere { 0, 1 texture { pigmnt { } } }", "unknown keyword 'pigmnt'; did you mean 'pigment'?", 1, 25},
    {"TextureNotWord", "sphere { 0, 1 texture { 1 } }", "expected 'pigment', 'finish', 'normal', a transform or '}' in texture, found '1'", 1, 25},
    {"TextureWrongName", "#declare F = finish { }\nsphere { 0, 1 texture { F } }", "'F' is a finish, not a texture", 2, 25},
    {"PigmentUnknown", "sphere { 0, 1 pigment { chequer } }", "unknown keyword 'chequer'; did you mean 'checker'?", 1, 25},
    {"PigmentNotWord", "sphere { 0, 1 pigment { } } }", "expected a statement (an object, camera, light_source, ...), found '}'", 1, 29},
    {"PigmentBadItem", "sphere { 0, 1 pigment { ; } }", "expected a colour, a pattern or '}' in pigment, found ';'", 1, 25},
    {"PigmentWrongName", "#declare F = finish { }\nsphere { 0, 1 pigment { F } }", "'F' is a finish, not a pigment or colour", 2, 25},
    {"BrickSize", "sphere { 0, 1 pigment { brick brick_size <1, 0, 1> } }", "'brick_size' components must be positive, got <1, 0, 1>", 1, 42},
    {"Mortar", "sphere { 0, 1 pigment { brick mortar -1 } }", "'mortar' must not be negative, got -1", 1, 38},
    {"GradientAxis", "sphere { 0, 1 pigment { gradient 0 } }", "gradient axis must not be a zero-length vector", 1, 34},
    {"ColorMapOrder", "sphere { 0, 1 pigment { gradient y color_map { [0.5 rgb 1] [0.2 rgb 0] } } }", "color_map values must not decrease", 1, 61},
    {"ColorMapEmpty", "sphere { 0, 1 pigment { gradient y color_map { } } }", "color_map has no entries", 1, 36},
    // texture_map, pigment_map, patterned and layered textures
    {"TextureMapNeedsBracket", "sphere { 0, 1 texture { gradient x texture_map { 0.5 pigment { rgb 1 } } } }", "expected '[' to start a texture_map entry, or '}', found '0.5'", 1, 50},
    {"TextureMapEntryUnclosed", "sphere { 0, 1 texture { gradient x texture_map { [0.5 pigment { rgb 1 } } } }", "expected 'pigment', 'finish', 'normal', a transform or ']' to end the texture_map entry, found '}'", 1, 73},
    {"TextureMapOrder", "sphere { 0, 1 texture { gradient x texture_map { [0.5 pigment { rgb 1 }] [0.2 pigment { rgb 0 }] } } }", "texture_map values must not decrease", 1, 75},
    {"TextureMapEmpty", "sphere { 0, 1 texture { gradient x texture_map { } } }", "texture_map has no entries", 1, 36},
    {"TextureMapMissing", "sphere { 0, 1 texture { gradient x } }", "a 'gradient' texture needs a texture_map", 1, 25},
    {"TextureMapNegativeWeight", "sphere { 0, 1 texture { average texture_map { [-1 pigment { rgb 1 }] } } }", "texture_map weights (with 'average') must not be negative", 1, 48},
    {"PigmentMapNeedsBracket", "sphere { 0, 1 pigment { gradient x pigment_map { rgb 1 } } }", "expected '[' to start a pigment_map entry, or '}', found 'rgb'", 1, 50},
    {"PigmentMapEntryUnclosed", "sphere { 0, 1 pigment { gradient x pigment_map { [0 rgb 1 } } }", "expected a colour, a pattern or ']' to end the pigment_map entry, found '}'", 1, 59},
    {"PigmentMapOrder", "sphere { 0, 1 pigment { gradient x pigment_map { [0.5 rgb 1] [0.25 rgb 0] } } }", "pigment_map values must not decrease", 1, 63},
    {"CheckerTextureCount", "sphere { 0, 1 texture { checker texture { pigment { rgb 1 } } } }", "'checker' needs 2 textures", 1, 25},
    {"CheckerTextureWithMap", "sphere { 0, 1 texture { checker texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } texture_map { [0 pigment { rgb 1 }] } } }", "'checker' takes its textures directly, not a texture_map", 1, 93},
    {"TilesNeedsTile2", "sphere { 0, 1 texture { tiles { texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } } } }", "expected 'tile2' or another 'texture' in tiles, found '}'", 1, 93},
    {"LayerOverPatterned", "sphere { 0, 1 texture { checker texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } } texture { pigment { rgbt 1 } } }", "cannot layer over a patterned texture (as POV-Ray)", 1, 95},
    {"PatternedLayer", "sphere { 0, 1 texture { pigment { rgb 1 } } texture { checker texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } } }", "cannot layer a patterned texture over another texture (as POV-Ray)", 1, 45},
    {"ColorMapBracket", "sphere { 0, 1 pigment { gradient y color_map { 0 rgb 1 } } }", "expected '[' to start a color_map entry, or '}', found '0'", 1, 48},
    {"ColorMapClose", "sphere { 0, 1 pigment { gradient y color_map { [0 rgb 1 } } }", "expected ']' to end the color_map entry, found '}'", 1, 57},
    {"FinishUnknown", "sphere { 0, 1 finish { phog 1 } }", "unknown keyword 'phog'; did you mean 'phong'?", 1, 24},
    {"FinishNotWord", "sphere { 0, 1 finish { 1 } }", "expected a finish keyword or '}', found '1'", 1, 24},
    {"FinishWrongName", "#declare P = pigment { }\nsphere { 0, 1 finish { P } }", "'P' is a pigment, not a finish", 2, 24},
    {"FinishNegative", "sphere { 0, 1 finish { diffuse -0.5 } }", "'diffuse' must not be negative, got -0.5", 1, 32},
    {"PhongNegative", "sphere { 0, 1 finish { phong -1 } }", "'phong' must not be negative, got -1", 1, 30},
    {"Roughness", "sphere { 0, 1 finish { roughness 0 } }", "'roughness' must be positive, got 0", 1, 34},
    {"ReflectionBlur", "sphere { 0, 1 finish { reflection_blur 2 } }", "'reflection_blur' must be between 0 and 1, got 2", 1, 40},
    {"RefractionBlur", "sphere { 0, 1 finish { refraction_blur -1 } }", "'refraction_blur' must be between 0 and 1, got -1", 1, 40},
    {"ReflectionFalloff", "sphere { 0, 1 finish { reflection { 1 falloff 0 } } }", "'falloff' must be positive, got 0", 1, 47},
    {"ReflectionUnknown", "sphere { 0, 1 finish { reflection { 1 fresnell } } }", "unknown keyword 'fresnell'; did you mean 'fresnel'?", 1, 39},
    {"ReflectionNotWord", "sphere { 0, 1 finish { reflection { 1 2 } } }", "expected 'fresnel', 'falloff', 'metallic' or '}' in reflection, found '2'", 1, 39},
    {"InteriorUnknown", "sphere { 0, 1 interior { iro 1 } }", "unknown keyword 'iro'; did you mean 'ior'?", 1, 26},
    {"InteriorNotWord", "sphere { 0, 1 interior { 1 } }", "expected an interior keyword or '}', found '1'", 1, 26},
    {"InteriorWrongName", "#declare P = pigment { }\nsphere { 0, 1 interior { P } }", "'P' is a pigment, not an interior", 2, 26},
    {"Ior", "sphere { 0, 1 interior { ior 0 } }", "'ior' must be positive, got 0", 1, 30},
    {"InteriorFadeDistance", "sphere { 0, 1 interior { fade_distance -1 } }", "'fade_distance' must not be negative, got -1", 1, 40},
    {"InteriorFadePower", "sphere { 0, 1 interior { fade_power -1 } }", "'fade_power' must not be negative, got -1", 1, 37},
    // algebraic shapes
    {"QuarticCoefficientCount", "quartic {\n  <1, 2, 3> }", "quartic coefficient list needs 35 numbers, found 3", 2, 3},
    {"CubicCoefficientCount", "cubic { <1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21> }", "cubic coefficient list needs 20 numbers, found 21", 1, 9},
    {"PolyCoefficientCount", "poly { 3, <1, 2> }", "poly coefficient list needs 20 numbers, found 2", 1, 11},
    {"PolyOrderRange", "poly { 1, <1, 2, 3, 4> }", "poly order must be a whole number from 2 to 35, not 1", 1, 8},
    {"PolyOrderWhole", "poly { 2.5, <1> }", "the poly order must be a whole number, got 2.5", 1, 8},
    {"PolyNeedsList", "poly { 2, 1 }", "expected '<' to open the poly coefficient list, found '1'", 1, 11},
    {"QuadricNeedsComma", "quadric { <1, 1, 1> <0, 0, 0>, <0, 0, 0>, -1 }", "expected ',' after the quadric's vector, found '<'", 1, 21},
    {"ConstantPolynomial", "poly { 2, <0, 0, 0, 0, 0, 0, 0, 0, 0, 5> }", "poly has no term in x, y or z: it defines no surface", 1, 1},
    {"SuperellipsoidCount", "superellipsoid { <1, 1, 1> }", "superellipsoid exponents <e, n> needs 2 numbers, found 3", 1, 18},
    {"SuperellipsoidPositive", "superellipsoid { <0, 1> }", "superellipsoid exponents must be positive", 1, 18},
    // julia_fractal
    {"JuliaQuaternionFunction", "julia_fractal { <0, 0, 0, 0> sin }", "a quaternion julia_fractal iterates 'sqr' or 'cube', not 'sin' (add 'hypercomplex' for the other functions)", 1, 30},
    {"JuliaPrecision", "julia_fractal { 0 precision 0.5 }", "the julia precision must be at least 1 (POV-Ray takes 1), got 0.5", 1, 29},
    {"JuliaMaxIteration", "julia_fractal {\n  0 max_iteration 0 }", "the julia max_iteration must be at least 1 (POV-Ray takes 1), got 0", 2, 19},
    {"JuliaSliceComma", "julia_fractal { 0 slice <0, 0, 0, 1> 0 }", "expected ',' after the slice normal, found '0'", 1, 38},
    {"JuliaPwrParen", "julia_fractal { 0 hypercomplex pwr 2, 1 }", "expected '(' after 'pwr', found '2'", 1, 36},
    // blob
    {"BlobThreshold", "blob { threshold 0 sphere { 0, 1, 1 } }", "the blob threshold must be positive, got 0", 1, 18},
    {"BlobNoComponent", "blob { threshold 0.5 }", "a blob needs at least one sphere or cylinder component", 1, 1},
    {"BlobRadius", "blob { sphere { 0, -1, 1 } }", "blob component radius must be positive, got -1", 1, 20},
    {"BlobStrengthZero", "blob {\n  sphere { 0, 1, strength 0 } }", "a blob component's strength must not be 0", 2, 27},
    {"BlobCylinderEnds", "blob { cylinder { <1, 0, 0>, <1, 0, 0>, 1, 1 } }", "a blob cylinder needs two different end points", 1, 30},
    {"BlobComponentComma", "blob { sphere { 0 1, 1 } }", "expected ',' after the point, found '1'", 1, 19},
    {"BlobComponentClose", "blob { sphere { 0, 1, 1 pigment { rgb 1 } } }", "expected '}' to close the blob sphere, found 'pigment'", 1, 25},
    // media
    {"MediaUnknown", "media { absorbtion 1 }", "unknown keyword 'absorbtion'; did you mean 'absorption'?", 1, 9},
    {"MediaNotWord", "media { 1 }", "expected a media keyword or '}', found '1'", 1, 9},
    {"MediaInInterior", "sphere { 0, 1 interior { media { emision 1 } } }", "unknown keyword 'emision'; did you mean 'emission'?", 1, 34},
    {"ScatteringType", "media { scattering { 6, 0.1 } }", "the scattering type must be 1, 2, 3, 4 or 5, got 6", 1, 22},
    {"ScatteringEccentricity", "media { scattering { 5, 0.1 eccentricity 1 } }", "'eccentricity' must lie strictly between -1 and 1, got 1", 1, 42},
    {"ScatteringExtinction", "media { scattering { 1, 0.1 extinction -1 } }", "'extinction' must not be negative, got -1", 1, 40},
    {"ScatteringUnknown", "media { scattering { 1, 0.1 eccentric 0.5 } }", "unknown keyword 'eccentric'; did you mean 'eccentricity'?", 1, 29},
    {"MediaIntervals", "media { intervals 0 }", "'intervals' must be at least 1, got 0", 1, 19},
    {"MediaSamples", "media { samples 5000 }", "'samples' 5000 is over the limit of 4096 (limit media_intervals = 4096; raise it with --limit media_intervals=N)", 1, 17},
    {"MediaMethod", "media { method 4 }", "'method' must be 1, 2 or 3, got 4", 1, 16},
    {"PolyWaveExponent", "sphere { 0, 1 pigment { bozo poly_wave -2 } }", "the 'poly_wave' exponent must be positive, got -2", 1, 40},
    {"PolyWaveExponentNormal", "sphere { 0, 1 normal { bumps poly_wave 0 } }", "the 'poly_wave' exponent must be positive, got 0", 1, 40},
    {"WaveMisspelt", "sphere { 0, 1 pigment { bozo sine_wav } }", "unknown keyword 'sine_wav'; did you mean 'sine_wave'?", 1, 30},
    {"FrequencyValue", "sphere { 0, 1 pigment { bozo frequency } }", "expected a value (a number, a vector <x, y, z> or a name), found '}'", 1, 40},
    {"WaveOnBlockTexture", "sphere { 0, 1 texture { checker texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } sine_wave } }", "unknown keyword 'sine_wave'", 1, 93},
    {"DensityUnknown", "media { density { bozzo } }", "unknown keyword 'bozzo'; did you mean 'bozo'?", 1, 19},
};
// clang-format on

INSTANTIATE_TEST_SUITE_P(All, ParserErrors, testing::ValuesIn(kCases),
                         [](const testing::TestParamInfo<ErrorCase>& info) { return std::string(info.param.name); });

TEST(ParserErrors, IncludesNestedTooDeeply) {
    const std::string dir = test::tempDir();
    for (int i = 0; i < 70; ++i)
        test::writeFile(dir + "/f" + std::to_string(i) + ".drt", "#include \"f" + std::to_string(i + 1) + ".drt\"\n");
    test::writeFile(dir + "/f70.drt", "sphere { 0, 1 }\n");
    Diagnostics diags;
    EXPECT_FALSE(loadSceneFile(dir + "/f0.drt", diags));
    ASSERT_EQ(diags.errorCount(), 1);
    EXPECT_EQ(diags.all()[0].message,
              "include depth 65 is over the limit of 64 (limit include_depth = 64; raise it with --limit include_depth=N)");
    EXPECT_EQ(diags.all()[0].loc.line, 1);
    EXPECT_EQ(diags.all()[0].loc.column, 10);
}

} // namespace
} // namespace drt

namespace drt {
namespace {

// Lines are found through an index of line starts made when the file is added
// (each #declare asks for its line): they must be what splitting at '\n' gives.
TEST(SourceFiles, LinesAreTheTextBetweenNewlines) {
    const std::vector<std::string> texts = {"", "a", "a\n", "a\nb", "\n\n\nlast", "one\r\ntwo\r\n\r\nfour", "x\n\ny\n"};
    SourceFiles files;
    for (const std::string& text : texts) {
        const int id = files.add("t.drt", text);
        std::vector<std::string> expected;
        size_t start = 0;
        for (;;) {
            const size_t end = text.find('\n', start);
            std::string line = text.substr(start, end == std::string::npos ? std::string::npos : end - start);
            if (!line.empty() && line.back() == '\r') line.pop_back();
            expected.push_back(line);
            if (end == std::string::npos) break;
            start = end + 1;
        }
        for (size_t i = 0; i < expected.size(); ++i)
            EXPECT_EQ(files.line(id, int(i) + 1), expected[i]) << "line " << i + 1 << " of '" << text << "'";
        EXPECT_EQ(files.line(id, int(expected.size()) + 1), "");
        EXPECT_EQ(files.line(id, 0), "");
        EXPECT_EQ(files.line(id, -3), "");
    }
}

} // namespace
} // namespace drt
