// The scene model: what every front end (.drt, .pov) builds and what the
// renderer consumes. It knows nothing of text or of Embree. Defaults follow
// POV-Ray 3.7 (docs/pov.md) unless stated.
#pragma once

#include "core/color.h"
#include "core/diagnostics.h"
#include "core/heap_optional.h"
#include "core/transform.h"
#include "core/vec.h"
#include "scene/algebraic.h"
#include "scene/blob.h"
#include "scene/extrusion.h"
#include "scene/fractal_pattern.h"
#include "scene/function.h"
#include "scene/indexed_mesh.h"
#include "scene/isosurface.h"
#include "scene/julia_fractal.h"
#include "scene/motion.h"

#include <algorithm>
#include "scene/revolution.h"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "scene/pattern_wave.h"

namespace drt {

// ---------------------------------------------------------------- textures

enum class PatternKind {
    Solid,    // `color ...`
    Checker,  // two sub-pigments in unit cubes
    Hexagon,  // three sub-pigments
    Brick,    // two sub-pigments (mortar, brick)
    Gradient, // colour map along `gradientAxis`
    Radial,   // colour map around y
    Onion,    // colour map by distance from the origin
    Spherical, // colour map of max(0, 1 - distance from the origin) (POV-Ray's spherical)
    Planar,    // colour map of max(0, 1 - |y|) (POV-Ray's planar)
    Cylindrical, // colour map of max(0, 1 - distance from the y axis) (POV-Ray's cylindrical)
    Boxed,     // colour map of max(0, 1 - max(|x|, |y|, |z|)) (POV-Ray's boxed)
    Function,  // colour map of a user-defined function's value (Pigment::function, scene/function.h)
    Fractal,   // colour map of POV-Ray's mandel, julia or magnet value (Pigment::fractal, scene/fractal_pattern.h)
    // Noise patterns (render/noise.h): drt's own gradient noise, shaped like
    // POV-Ray's documented patterns but not value-for-value equal to them.
    Bozo,     // colour map of plain noise (POV-Ray's bozo and spotted)
    Granite,  // sum of |noise| octaves at doubling frequency
    Marble,   // triangle wave along x, turbulence added
    Wood,     // concentric cylinders around the z axis
    Agate,    // sine of z plus strong built-in turbulence
    Leopard,  // squared sum of sines: regular spots
    Crackle,  // cellular: distance to the nearest feature point
    Wrinkles, // bump patterns, usable as pigments too
    Dents,
    Bumps,
    Ripples,  // concentric waves around fixed centres
    Waves,
    // The weighted mean of every pigment_map / texture_map entry, each entry's
    // map value being its weight (POV-Ray's `average`).
    Average,
    ImageMap, // an image file (scene/image_map.h)
    ImagePattern, // colour map of an image's grey value (Pigment::imageMap, its texels as the file stores them)
    DensityFile, // a df3 voxel file over the unit cube (Pigment::densityFile, scene/density_file.h)
};

// POV-Ray turbulence: the pattern is evaluated at p + amount * T(p), with T a
// sum of `octaves` vector-noise octaves whose weight scales by `omega` and
// frequency by `lambda` each octave. No effect while amount is zero.
struct Turbulence {
    Vec3 amount{0, 0, 0};
    int octaves = 6;
    double omega = 0.5;
    double lambda = 2.0;
};

struct ColorMapEntry {
    double value = 0;
    ColorFT color;
};

struct ImageMap;
struct DensityFile;

struct Pigment {
    PatternKind pattern = PatternKind::Solid;
    std::shared_ptr<const ImageMap> imageMap; // ImageMap, ImagePattern: the decoded image and its mapping
    std::shared_ptr<const Function> function; // Function: its value at the pattern point
    std::shared_ptr<const FractalPattern> fractal; // Fractal: which fractal, with its parameters
    std::shared_ptr<const DensityFile> densityFile; // DensityFile: the file and, once resolved, its voxels
    ColorFT color;                        // Solid (POV-Ray default: black)
    std::vector<Pigment> children;        // Checker, Hexagon, Brick sub-pigments
    std::vector<ColorMapEntry> colorMap;  // Gradient, Radial, Onion
    Vec3 gradientAxis{0, 1, 0};
    Vec3 brickSize{8, 3, 4.5};
    double mortar = 0.5;
    Turbulence turbulence; // noise and colour-map patterns
    PatternWave wave;      // value patterns (not block patterns or image maps)
    // Pattern space -> world space, including the transforms of the object the
    // pigment belongs to that came after it. Evaluate at toWorld.inversePoint(p).
    Transform toWorld;
    // pigment_map: when non-empty it replaces colorMap; the two entries around
    // the pattern value are evaluated and blended like colour-map entries.
    struct MapEntry;
    std::vector<MapEntry> pigmentMap;
    // POV-Ray's uv_mapping: the pattern is evaluated at (u, v, 0) of the
    // surface's uv coordinates (Hit::uv) mapped by toWorld's inverse, and the
    // object's transforms do not move it (transformPigmentSpaces leaves it).
    // On a surface without uv coordinates it is evaluated at (0, 0, 0).
    bool uvMapping = false;
};

struct Pigment::MapEntry {
    double value = 0;
    Pigment pigment;
};

struct Finish {
    Color ambient{0.1};
    Color emission{0};
    double diffuse = 0.6;
    double brilliance = 1;
    double phong = 0;
    double phongSize = 40;
    double specular = 0;
    double roughness = 0.05;
    double metallic = 0;
    // reflection: `reflection r` sets both min and max to r.
    Color reflectionMin{0};
    Color reflectionMax{0};
    bool reflectionFresnel = false;
    double reflectionFalloff = 1;
    // `reflection { ... metallic m }`: tints reflected light by the pigment, by m.
    double reflectionMetallic = 0;
    bool conserveEnergy = false;
    // Distribution ray tracing (drt extension, docs/effects.md). 0 is a perfect mirror /
    // perfect refraction; larger values widen the lobe around the ideal direction.
    double reflectionBlur = 0;
    double refractionBlur = 0;
    // POV-Ray crand: each light's diffuse term loses U crand before it is
    // multiplied by the pigment and light colours, U uniform in [0, 1) and
    // drawn anew per light, bounce and pixel sample (graininess).
    double crand = 0;
};

// A slope_map entry: at pattern value `value` the bump height is `height` and
// its slope `slope` (per unit of the interval to the neighbouring entry).
struct SlopeMapEntry {
    double value = 0;
    double height = 0;
    double slope = 0;
};

// A normal pattern (POV-Ray `normal { bumps 0.4 scale 0.2 }`), with
// POV-Ray's rules (render/normal_pattern.cpp): bumps, dents, wrinkles,
// ripples and waves have formulas of their own; every other pattern tilts the
// normal down its slope, sampled `accuracy` apart in pattern space.
struct Normal {
    PatternKind pattern = PatternKind::Bumps;
    double amount = 0.5;
    Turbulence turbulence;
    PatternWave wave; // shapes the pattern's value (not for the five with formulas of their own)
    Transform toWorld; // as Pigment::toWorld
    Vec3 gradientAxis{0, 1, 0}; // Gradient
    std::shared_ptr<const Function> function; // Function
    std::shared_ptr<const FractalPattern> fractal; // Fractal
    std::shared_ptr<const DensityFile> densityFile; // DensityFile
    double accuracy = 0.02;     // POV-Ray's `accuracy`: the slope's sample spacing
    // slope_map: the slope method samples the height this map gives the
    // pattern value (cubic Hermite between entries) instead of the value itself.
    std::vector<SlopeMapEntry> slopeMap;
    // uv_mapping: the pattern lives in the surface's uv space (u, v, 0), which
    // the object's transforms do not move; its tilt is carried to the surface by
    // the uv tangent frame (render/normal_pattern.h). Surfaces without uv
    // coordinates show no bumps then.
    bool uvMapping = false;
};

// A plain texture is one layer: pigment, finish, normal. Two extensions, both
// empty for a plain texture (render/texture_shading.h gives their shading):
// - `map` makes it a patterned texture (texture_map, or checker / hexagon /
//   brick / tiles of textures): `pigment` then only carries the pattern (kind,
//   gradient axis, brick size, turbulence, pattern space); block patterns pick
//   the entry by index, the others blend the two entries around the pattern
//   value, Average all of them. finish and normal are unused.
// - `layersAbove` are further layers on top of this one, lowest first (POV-Ray's
//   `texture {A} texture {B}` is A with layersAbove {B}).
struct Texture {
    Pigment pigment;
    Finish finish;
    HeapOptional<Normal> normal; // none: the surface's own normal (on the heap: most textures have none)
    struct MapEntry;
    std::vector<MapEntry> map;
    std::vector<Texture> layersAbove;

    bool plain() const { return map.empty() && layersAbove.empty(); }
};

struct Texture::MapEntry {
    double value = 0; // the pattern value (texture_map) or weight (Average); unused by block patterns
    Texture texture;
};

// True if the texture or any of its layers is a patterned texture. POV-Ray
// layers only plain textures ("Cannot layer over a patterned texture"); both
// front ends refuse the same.
inline bool hasPatternedLayer(const Texture& t) {
    if (!t.map.empty()) return true;
    for (const Texture& layer : t.layersAbove)
        if (hasPatternedLayer(layer)) return true;
    return false;
}

// Puts `top` (with its own layers) on top of `bottom`'s layers.
inline void addLayerOnTop(Texture& bottom, Texture top) {
    std::vector<Texture> above = std::move(top.layersAbove);
    top.layersAbove.clear();
    bottom.layersAbove.push_back(std::move(top));
    for (Texture& layer : above) bottom.layersAbove.push_back(std::move(layer));
}

// Applies a transform after the pattern space of a pigment and of all its sub-pigments.
inline void transformPigmentSpaces(Pigment& p, const Transform& t) {
    if (!p.uvMapping) p.toWorld = p.toWorld.then(t);
    for (Pigment& child : p.children) transformPigmentSpaces(child, t);
    for (Pigment::MapEntry& entry : p.pigmentMap) transformPigmentSpaces(entry.pigment, t);
}

// Applies a transform to every pattern space of a texture (pigment tree and
// normal), its map entries and its layers.
inline void transformTextureSpaces(Texture& texture, const Transform& t) {
    transformPigmentSpaces(texture.pigment, t);
    if (texture.normal && !texture.normal->uvMapping) texture.normal->toWorld = texture.normal->toWorld.then(t);
    for (Texture::MapEntry& entry : texture.map) transformTextureSpaces(entry.texture, t);
    for (Texture& layer : texture.layersAbove) transformTextureSpaces(layer, t);
}

// POV-Ray participating media (`media { }`; render/media.h has the estimator).
// At a point p with density D(p) (the product of the densities' colours, 1
// without any), the medium absorbs D a, emits D e and scatters D s per unit
// length; the extinction is D (a + extinction s). Scattering types are
// POV-Ray's: 1 isotropic, 2 Mie haze, 3 Mie murky, 4 Rayleigh, 5
// Henyey-Greenstein with `eccentricity`. N = intervals x samples stratified
// jittered samples per ray segment; POV-Ray's method, confidence, variance,
// ratio, jitter and aa_* are accepted by the front ends but not kept.
struct Media {
    Color absorption{0};
    Color emission{0};
    int scatteringType = 0; // 0: no scattering block
    Color scattering{0};
    double eccentricity = 0;
    double extinction = 1;
    int intervals = 1;
    int samples = 1;
    std::vector<Pigment> densities; // evaluated as colours, multiplied
};

struct Interior {
    double ior = 1;
    double fadeDistance = 0; // 0: no attenuation inside
    double fadePower = 0;
    Color fadeColor{0};
    std::vector<Media> media; // seen along rays inside the object (POV-Ray: the object must be hollow)
};

// Applies a transform after the pattern spaces of an interior's media densities.
inline void transformInteriorSpaces(Interior& interior, const Transform& t) {
    for (Media& m : interior.media)
        for (Pigment& d : m.densities) transformPigmentSpaces(d, t);
}

// ---------------------------------------------------------------- shapes
// Every shape is given in object space; Object::transform maps it to world space.
//
// Each shape type says, next to its numbers, what the layers above ask of every
// shape, so that a new shape is its type here, its intersection (accel/shapes.h
// and .cpp) and its front-end entry (one lang/shapes_*.cpp), and the compiler
// refuses it until each is given:
//   bool bounds(Vec3& lower, Vec3& upper) const  object-space box; false: unbounded
//                                                (scene/bounds.cpp; CSG, meshes, blobs,
//                                                extrusions and lathes are bounded there)
//   bool closedSolid() const   a closed surface around a solid inside, so that a ray
//                              leaving it proves it started inside (render/scene_warnings.cpp)
//   operator==                 equal in every number that shapes it (animation/clock_motion.cpp)

struct Sphere {
    Vec3 center;
    double radius = 1;
    bool bounds(Vec3& lower, Vec3& upper) const {
        lower = center - Vec3(radius), upper = center + Vec3(radius);
        return true;
    }
    bool closedSolid() const { return true; }
    bool operator==(const Sphere&) const = default;
};
struct Plane { // points p with dot(normal, p) = distance; inside is dot < distance
    Vec3 normal{0, 1, 0};
    double distance = 0;
    bool bounds(Vec3&, Vec3&) const { return false; }
    // A plane's inside (a half-space) holds the camera whenever a wall faces away from it.
    bool closedSolid() const { return false; }
    bool operator==(const Plane&) const = default;
};
struct Box {
    Vec3 corner1{-1, -1, -1};
    Vec3 corner2{1, 1, 1};
    bool bounds(Vec3& lower, Vec3& upper) const {
        lower = min(corner1, corner2), upper = max(corner1, corner2);
        return true;
    }
    bool closedSolid() const { return true; }
    bool operator==(const Box&) const = default;
};
struct Cylinder {
    Vec3 base;
    Vec3 cap{0, 1, 0};
    double radius = 1;
    bool open = false;
    bool bounds(Vec3& lower, Vec3& upper) const {
        lower = min(base, cap) - Vec3(radius), upper = max(base, cap) + Vec3(radius);
        return true;
    }
    bool closedSolid() const { return !open; }
    bool operator==(const Cylinder&) const = default;
};
struct Cone {
    Vec3 base;
    double baseRadius = 1;
    Vec3 cap{0, 1, 0};
    double capRadius = 0;
    bool open = false;
    bool bounds(Vec3& lower, Vec3& upper) const {
        const double r = std::max(baseRadius, capRadius);
        lower = min(base, cap) - Vec3(r), upper = max(base, cap) + Vec3(r);
        return true;
    }
    bool closedSolid() const { return !open; }
    bool operator==(const Cone&) const = default;
};
struct Disc {
    Vec3 center;
    Vec3 normal{0, 1, 0};
    double radius = 1;
    double holeRadius = 0;
    bool bounds(Vec3& lower, Vec3& upper) const {
        lower = center - Vec3(radius), upper = center + Vec3(radius);
        return true;
    }
    bool closedSolid() const { return false; }
    bool operator==(const Disc&) const = default;
};
struct Torus { // around the y axis
    double majorRadius = 1;
    double minorRadius = 0.25;
    bool bounds(Vec3& lower, Vec3& upper) const {
        const double r = majorRadius + minorRadius;
        lower = {-r, -minorRadius, -r}, upper = {r, minorRadius, r};
        return true;
    }
    bool closedSolid() const { return true; }
    bool operator==(const Torus&) const = default;
};
// A mesh read from a file after parsing (src/assets fills vertices and
// triangles): the file and what the scene said about it.
struct MeshSource {
    enum class Kind {
        PovHeightField, // POV-Ray's height_field image rules
        ModelFile,      // OBJ, PLY, glTF 2.0 through assimp (assets/model_load.cpp)
    };
    Kind kind = Kind::PovHeightField;
    std::string path; // found by the front end
    bool smooth = false;
    double waterLevel = 0;
    SourceLoc loc; // the file name in the scene
};

struct BicubicPatch;
struct Mesh {
    // The file of the triangles: to be read while `indexed` is empty (src/assets); a model file's stays set.
    std::shared_ptr<const MeshSource> source;
    std::vector<Vec3> vertices;
    std::vector<std::array<int, 3>> triangles;
    // Optional per-vertex normals (smooth_triangle, mesh2 normal_vectors);
    // when present, normalIndices has one entry per triangle.
    std::vector<Vec3> normals;
    std::vector<std::array<int, 3>> normalIndices;
    // The compact form (scene/indexed_mesh.h): when set, the vectors above are
    // empty and the triangles are here. Copies of the Mesh share it, and the
    // accelerator builds one BVH for all the objects that show it.
    std::shared_ptr<const IndexedMesh> indexed;
    // The bicubic_patch the triangles were made from (scene/bicubic_patch.h):
    // what the writer writes back instead of the triangles.
    std::shared_ptr<const BicubicPatch> patch;
    // Textures of single triangles (IndexedMesh::faceTextures index them);
    // the others take the object's texture. In the mesh's object space, like
    // Object::texture.
    std::vector<Texture> textures;
    bool closedSolid() const { return false; } // a mesh has no dependable inside
};

struct Object;
struct Csg {
    enum class Op { Union, Merge, Difference, Intersection };
    Op op = Op::Union;
    std::vector<Object> children;
};

// Algebraic and Superellipsoid: scene/algebraic.h; Extrusion: scene/extrusion.h;
// Revolution: scene/revolution.h; Blob: scene/blob.h; Isosurface: scene/isosurface.h;
// JuliaFractal: scene/julia_fractal.h.
using Shape = std::variant<Sphere, Plane, Box, Cylinder, Cone, Disc, Torus, Mesh, Csg, Algebraic, Superellipsoid,
                           Extrusion, Revolution, Blob, Isosurface, JuliaFractal>;

// An object's texture, kept on the heap and shared by the objects that have
// the same one: a texture is most of an object's size (about 850 of 1400
// bytes), and a scene of many objects mostly repeats a few textures (the front
// ends share equal ones as they place objects, scene/texture_sharing.h).
// Reading goes through ->, * or a const Texture&; edit() gives this object a
// copy of its own first when the texture is shared (copy on write), so
// changing one object's texture never changes another's.
class SharedTexture {
public:
    SharedTexture(); // the default texture, one for the whole process
    SharedTexture(Texture texture) : texture_(std::make_shared<Texture>(std::move(texture))) {}

    const Texture& operator*() const { return *texture_; }
    const Texture* operator->() const { return texture_.get(); }
    operator const Texture&() const { return *texture_; }
    Texture& edit(); // this object's own texture, copied first if shared
    // The texture every holder of it sees, for a change that applies to each
    // alike (resolving the files it names): not for what differs per object.
    Texture& editForEverySharer() { return *texture_; }
    bool sharedWith(const SharedTexture& other) const { return texture_ == other.texture_; }

private:
    std::shared_ptr<Texture> texture_;
};

struct Object {
    Shape shape;
    Transform transform; // object -> world (the transforms before the first motion)
    MotionChain motion;  // motions and the transforms after each (scene/motion.h); empty: still
    SharedTexture texture;
    Interior interior;
    bool noShadow = false;
    bool hollow = false;
    bool inverse = false;
    // clipped_by (POV-Ray): the object's surface is kept only where it lies
    // inside every one of these; their own surfaces are not added, so the
    // object may be left open. As for insideness (CSG), the object counts as
    // inside only where it is inside every clip too. Clip objects live in the
    // space Object::transform maps to (world for a top-level object, the CSG's
    // space for a member); transforms written after clipped_by move them too.
    // A moving top-level object's clips are in its rest pose's world (the
    // front ends fold the transforms after its motions in) and move with it.
    std::vector<Object> clippedBy;
    // POV-Ray's light_group: the object is lit by the lights of its group and
    // of the groups around it (Scene::lightGroupParents), and by the scene's
    // other lights only with globalLights. 0: no group (every light but the
    // groups' own).
    int lightGroup = 0;
    bool globalLights = true;
    SourceLoc loc;
};

// Moves an object's textures by `t`: its own and its mesh triangles' (both
// are placed like the object).
inline void transformObjectTextures(Object& o, const Transform& t) {
    transformTextureSpaces(o.texture.edit(), t);
    if (Mesh* mesh = std::get_if<Mesh>(&o.shape))
        for (Texture& own : mesh->textures) transformTextureSpaces(own, t);
}

// ---------------------------------------------------------------- lights

// Where an area light's n1 x n2 sample points go (docs/effects.md; the estimators are
// in render/lighting.h).
enum class AreaSampling {
    PovGrid,    // POV-Ray's method: every point of the edge-to-edge n1 x n2 grid at every hit
    Stratified, // Cook: the pixel's samples stratified over the rectangle, one shadow ray per sample once spp >= n1 n2
    SolidAngle, // Urena, Fajardo & King 2013: the same, uniform in solid angle
    Grid,       // POV-Ray's grid points (jittered with `jitter`), shared out over the pixel's samples like Stratified
};

struct AreaLight {
    Vec3 axis1{1, 0, 0};
    Vec3 axis2{0, 0, 1};
    int size1 = 1;
    int size2 = 1;
    bool jitter = false;
    int adaptive = -1; // POV-Ray `adaptive`; -1: not given (full grid)
    bool circular = false;
    bool orient = false;
    // The scene model's default is POV-Ray's grid points, one per camera
    // sample (the POV-Ray front end's choice); the .drt parser sets Stratified
    // (Cook's full area illumination is drt's documented default).
    AreaSampling sampling = AreaSampling::Grid;
};

struct LightMotion;

struct Scene;

struct Light {
    Vec3 position;
    Color color{1};
    bool shadowless = false;
    // Spotlight (POV-Ray defaults).
    bool spotlight = false;
    Vec3 pointAt{0, 0, 1};
    // POV-Ray's `parallel`: the light's rays all run along point_at - position.
    // A point lit by it sees the light as from its own projection onto the
    // plane through the position square to that direction (parallelLightPosition).
    bool parallel = false;
    double radius = 30;  // degrees
    double falloff = 45; // degrees
    double tightness = 0;
    // fade_distance 0: no distance falloff.
    double fadeDistance = 0;
    double fadePower = 0;
    std::optional<AreaLight> area;
    // POV-Ray's default averages only the shadow over an area light; with
    // area_illumination each sample point shades as a point light.
    bool areaIllumination = false;
    // drt's radiometric light (`inverse_square`): a point light of colour C gives
    // irradiance C cos(theta) / r^2; an area light is a two-sided Lambertian
    // rectangle of radiance C / area. Off: POV-Ray's lights, no distance falloff.
    bool inverseSquare = false;
    // POV-Ray media_interaction: the light scatters in media. media_attenuation:
    // media on the way dim the light (drt's default; POV-Ray's is off, which
    // the POV front end sets).
    bool mediaInteraction = true;
    bool mediaAttenuation = true;
    // Time (render/light_path.h): how the light moves over the shutter; null
    // for a light that stays still.
    std::shared_ptr<const LightMotion> motion;
    // The light_group the light belongs to (Object::lightGroup); 0: none, it
    // lights every object outside the groups and those with globalLights.
    int group = 0;
    // POV-Ray's projected_through: the light reaches a point only along a ray
    // that crosses these objects (a scene of their own, in world space, never
    // drawn), and only what lies between the point and the ray's first
    // crossing casts a shadow. Null: an ordinary light.
    std::shared_ptr<const Scene> projectedThrough;
    SourceLoc loc;
};

// Where a parallel light stands as seen from `point`: back along the light's
// unit direction u (point_at - position) by the point's distance h to the
// plane through the position square to u, point - u h. For a point before the
// plane that is its projection onto the plane; a point behind it sees the light
// from the same direction -u (as POV-Ray lights it), as far away.
inline Vec3 parallelLightPosition(const Light& light, const Vec3& point) {
    const Vec3 d = light.pointAt - light.position;
    const double len = length(d);
    if (!(len > 0)) return light.position;
    const Vec3 u = d / len;
    const double h = std::fabs(dot(u, point - light.position));
    return point - u * (h > 0 ? h : 1e-9);
}

// A light's pose at one time (an animated scene evaluated at that clock value).
struct LightKey {
    double time = 0;
    Vec3 position, pointAt, axis1, axis2; // axes: of the area light, if any
};

struct LightMotion {
    std::vector<LightKey> keys; // increasing times; interpolated linearly
    MotionChain chain;          // then moved by this (position, point_at as points, axes as vectors)
};

// ---------------------------------------------------------------- camera

// How image positions map to ray directions: Planar is the perspective (or,
// with CameraSpec::orthographic, the orthographic) camera.
enum class CameraMapping {
    Planar, Fisheye, UltraWideAngle, Panoramic, Cylinder1, Cylinder2, Cylinder3, Cylinder4, Spherical, Omnimax
};

// The camera as written; resolveCamera() (render/camera.h) turns it into
// vectors once the image size is known.
struct CameraSpec {
    Vec3 location{0, 0, 0};
    Vec3 direction{0, 0, 1};
    Vec3 up{0, 1, 0};
    std::optional<Vec3> right; // drt: defaults to x * width/height; POV front end sets <1.33,0,0>
    Vec3 sky{0, 1, 0};
    std::optional<Vec3> lookAt;
    std::optional<double> angle; // horizontal field of view, degrees
    // Orthographic projection (POV-Ray): rays parallel to direction, starting
    // on the plane through location spanned by right and up, whose lengths are
    // the view's width and height. With angle, right and up are scaled
    // together so that the width is 2 d tan(angle / 2), d the distance from
    // location to look_at (|direction| without look_at). No lens (aperture 0).
    bool orthographic = false;
    // POV-Ray's non-planar cameras (render/camera.h gives each one's rays).
    // Only with orthographic false; angle is then the mapping's angle (it does
    // not rescale direction) and defaults to 90, spherical's to 360 with
    // verticalAngle angle / 2. No lens (aperture 0).
    CameraMapping mapping = CameraMapping::Planar;
    std::optional<double> verticalAngle; // spherical only
    // Thin lens (docs/effects.md). aperture is the lens *diameter* in scene units; 0 is a pinhole.
    double aperture = 0;
    std::optional<Vec3> focalPoint;
    std::optional<double> focalDistance;
    // Shutter interval in scene time; objects' Motion spans time 0..1.
    double shutterOpen = 0;
    double shutterClose = 0;
    // Placement (render/camera_path.h): the resolved camera is moved by
    // `transform`, then by the motion chain at each ray's time.
    Transform transform;
    MotionChain motion;
    SourceLoc loc;
};

// The camera as written at one time (an animated scene evaluated at that
// clock value): Scene::cameraKeys, interpolated by render/camera_path.h.
struct CameraKey {
    double time = 0;
    CameraSpec camera;
};

// ---------------------------------------------------------------- settings

// POV-Ray's radiosity { }: diffuse interreflection. A surface's diffuse share
// of the light arriving over its hemisphere, diffuse * pigment * brightness
// times the mean radiance the hemisphere sends (cosine-weighted), added up to
// recursionLimit diffuse bounces deep; render/integrator.h estimates it with
// one cosine-distributed ray per shaded layer and camera sample.
struct Radiosity {
    int recursionLimit = 2;
    double brightness = 1;
};

struct GlobalSettings {
    int maxTraceLevel = 5;
    Color ambientLight{1};
    double assumedGamma = 1.0;
    double adcBailout = 1.0 / 255.0;
    std::optional<Radiosity> radiosity;
};

// The most shadow rays `light_samples` lets an area light send from a shading
// point at one camera sample.
constexpr int kMaxLightSamples = 1024;

// Image size and sampling set from the scene; the command line overrides them
// (overlaySettings). An empty value means "not set here".
struct RenderSettings {
    std::optional<int> width;
    std::optional<int> height;
    std::optional<int> samplesPerPixel;
    std::optional<uint64_t> seed;
    std::optional<std::string> sampler;
    std::optional<std::string> filter;
    // Adaptive sampling (`adaptive { error E min_samples a max_samples b }`);
    // see render/render.h RenderOptions.
    std::optional<bool> adaptive;
    std::optional<double> adaptiveError;
    std::optional<int> minSamplesPerPixel;
    std::optional<int> maxSamplesPerPixel;
    // Shadow rays per area light per shading point per camera sample
    // (`light_samples K`, 1 to kMaxLightSamples); see render/render.h RenderOptions.
    std::optional<int> lightSamples;
    // Worker threads: only ever set by the caller (0: all cores), never by a scene.
    std::optional<int> threads;
};

// `base` with every value that `top` sets replaced by top's.
inline RenderSettings overlaySettings(RenderSettings base, const RenderSettings& top) {
    auto take = [](auto& to, const auto& from) {
        if (from) to = from;
    };
    take(base.width, top.width);
    take(base.height, top.height);
    take(base.samplesPerPixel, top.samplesPerPixel);
    take(base.seed, top.seed);
    take(base.sampler, top.sampler);
    take(base.filter, top.filter);
    take(base.adaptive, top.adaptive);
    take(base.adaptiveError, top.adaptiveError);
    take(base.minSamplesPerPixel, top.minSamplesPerPixel);
    take(base.maxSamplesPerPixel, top.maxSamplesPerPixel);
    take(base.lightSamples, top.lightSamples);
    take(base.threads, top.threads);
    return base;
}

// POV-Ray fog. Along a ray segment of fog depth z (the path length for
// constant fog; for ground fog the path integral of the density below), the
// transmittance is T = max(exp(-z / distance), color.transmit) and what is
// seen becomes (1 - T) C + T ((1 - f) + f C) * seen, with C the fog colour and
// f its filter (POV-Ray's atmosph.cpp do_fog). Rays that miss everything have length 1e7 (POV-Ray's
// Max_Distance), so constant fog covers the background fully.
struct Fog {
    enum class Type { Constant, Ground }; // POV-Ray fog_type 1, 2
    Type type = Type::Constant;
    double distance = 1;
    ColorFT color;
    // Ground fog: density 1 at heights h = dot(p, up) below offset, and
    // 1 / (1 + ((h - offset) / altitude)^2) above it.
    double offset = 0;
    double altitude = 1;
    Vec3 up{0, 1, 0};
    // POV-Ray's turbulent fog (atmosph.cpp): with P the segment's midpoint
    // scaled by turbulence.amount, the depth z becomes
    // z (1 - exp(-length / distance) min(1, turb(P) turbDepth)), turb a sum of
    // |noise| octaves (drt's noise, so not value-for-value POV-Ray's).
    std::optional<Turbulence> turbulence;
    double turbDepth = 0.5;
};

struct Scene {
    CameraSpec camera;
    std::vector<CameraKey> cameraKeys; // empty, or the camera over the shutter (increasing times)
    std::vector<Light> lights;
    std::vector<Object> objects;
    Color background{0};
    // POV-Ray sky_sphere: pigments evaluated at the unit direction of rays that
    // miss everything, the last one on top; what their filter/transmit lets
    // through shows the background colour. Empty: the background alone.
    std::vector<Pigment> sky;
    std::vector<Fog> fogs; // each over the whole ray segment: colours add, transmittances multiply (POV-Ray)
    std::vector<Media> media; // atmospheric media: everywhere outside non-hollow objects
    GlobalSettings global;
    RenderSettings render;
    // The scene text read `clock` (scene/frame_clock.h): with the shutter open,
    // the scene is evaluated again over it to find how it moves.
    bool readsClock = false;
    // light_group nesting: entry g is the group around group g (0: none);
    // entry 0 is unused.
    std::vector<int> lightGroupParents{0};
};

// Whether `light` shines on `object` (POV-Ray's light_group): a group's light
// lights its group's objects and those of the groups inside it; a light of no
// group lights the objects of no group and those with globalLights. Every
// object casts shadows either way.
inline bool lightReaches(const Scene& scene, const Light& light, const Object& object) {
    if (light.group == 0) return object.lightGroup == 0 || object.globalLights;
    const size_t groups = scene.lightGroupParents.size();
    size_t hops = 0; // parents point outward, so at most `groups` steps
    for (int g = object.lightGroup; g > 0 && size_t(g) < groups && hops < groups; g = scene.lightGroupParents[size_t(g)], ++hops)
        if (g == light.group) return true;
    return false;
}

} // namespace drt
