// Shapes and object modifiers. Texture transforms follow POV-Ray: a texture
// given to an object moves with every transform of the object that follows it.
#include "lang/parser.h"

#include <algorithm>
#include <cmath>

namespace drt {

static const std::vector<std::string>& objectWords() {
    static const std::vector<std::string> words{"sphere", "plane",    "box",             "cylinder", "cone",
                                                "disc",   "torus",    "triangle",        "smooth_triangle",
                                                "mesh",   "union",    "merge",           "difference",
                                                "intersection", "object",
                                                "quadric", "cubic", "quartic", "poly", "superellipsoid", "prism", "text",
                                                "lathe", "sor", "blob"};
    return words;
}

static const std::vector<std::string>& modifierWords() {
    static const std::vector<std::string> words{"translate", "rotate", "scale",  "matrix",    "texture",
                                                "pigment",   "finish", "normal", "interior", "no_shadow", "hollow",
                                                "inverse",   "motion", "open", "clipped_by"};
    return words;
}

bool Parser::atObjectWord() const {
    if (current_.kind != TokenKind::Identifier) return false;
    const auto& words = objectWords();
    return std::find(words.begin(), words.end(), current_.text) != words.end();
}

static bool isCsg(const ParsedObject& po) { return std::holds_alternative<Csg>(po.object.shape); }
// merge, difference and intersection stay one object with its children (true
// CSG in the accelerator); a union is flattened into its members.
static bool isSolidCsg(const ParsedObject& po) {
    const Csg* csg = std::get_if<Csg>(&po.object.shape);
    return csg && csg->op != Csg::Op::Union;
}

double Parser::positiveRadius(const char* what) {
    const SourceLoc loc = current_.loc;
    const double r = floatExpr(what);
    if (r <= 0) {
        error(loc, std::string(what) + " must be positive");
        return 1;
    }
    return r;
}

// object = shape-keyword "{" shape-body { object-modifier } "}"
//        | "object" "{" name { object-modifier } "}"
ParsedObject Parser::object() {
    const Token keyword = current_;
    advance();
    DepthGuard guard(*this, keyword.loc);
    expect(TokenKind::LeftBrace, ("'{' after '" + keyword.text + "'").c_str());
    ParsedObject po;
    if (keyword.text == "object") {
        if (atObjectWord()) {
            po = object(); // POV-Ray allows object { sphere { ... } modifiers }
        } else {
            const Token name = expect(TokenKind::Identifier, "the name of a declared object");
            const Value* v = lookup(name.text);
            if (!v) {
                std::vector<std::string> known;
                for (const auto& [n, value] : symbols_)
                    if (std::holds_alternative<ParsedObject>(value)) known.push_back(n);
                failUnknown(name, known, "object");
            }
            if (!std::holds_alternative<ParsedObject>(*v))
                fail(name.loc, "'" + name.text + "' is " + kindName(*v) + ", not an object");
            countBuilt(name.loc, symbolWeights_[name.text]);
            po = std::get<ParsedObject>(*v);
        }
    } else {
        countBuilt(keyword.loc, 1);
        po.object.loc = keyword.loc;
        shapeBody(keyword, po);
    }
    objectModifiers(po, keyword);
    return po;
}

void Parser::shapeBody(const Token& keyword, ParsedObject& po) {
    const std::string& w = keyword.text;
    Shape& shape = po.object.shape;
    auto comma = [&](const char* after) { expect(TokenKind::Comma, (std::string("',' after the ") + after).c_str()); };
    if (w == "sphere") {
        Sphere s;
        s.center = vectorExpr("the centre <x, y, z>");
        comma("centre");
        s.radius = positiveRadius("sphere radius");
        shape = s;
    } else if (w == "plane") {
        Plane p;
        const SourceLoc loc = current_.loc;
        Vec3 n = vectorExpr("the normal <x, y, z>");
        comma("normal");
        double d = floatExpr("the distance");
        // POV-Ray normalises the normal and divides the distance by its length,
        // which keeps the plane dot(n, p) = d where it was.
        const double len = length(n);
        if (len == 0) {
            error(loc, "plane normal must not be a zero-length vector");
            n = {0, 1, 0};
        } else {
            n = n / len;
            d /= len;
        }
        p.normal = n;
        p.distance = d;
        shape = p;
    } else if (w == "box") {
        Box b;
        b.corner1 = vectorExpr("a corner <x, y, z>");
        comma("first corner");
        b.corner2 = vectorExpr("a corner <x, y, z>");
        shape = b;
    } else if (w == "cylinder") {
        Cylinder c;
        c.base = vectorExpr("the base point");
        comma("base point");
        const SourceLoc capLoc = current_.loc;
        c.cap = vectorExpr("the cap point");
        comma("cap point");
        c.radius = positiveRadius("cylinder radius");
        if (c.base == c.cap) {
            error(capLoc, "cylinder base and cap are the same point (zero-length axis)");
            c.cap = c.base + Vec3(0, 1, 0);
        }
        shape = c;
    } else if (w == "cone") {
        Cone c;
        c.base = vectorExpr("the base point");
        comma("base point");
        SourceLoc loc = current_.loc;
        c.baseRadius = floatExpr("the base radius");
        if (c.baseRadius < 0) error(loc, "cone radius must not be negative");
        comma("base radius");
        const SourceLoc capLoc = current_.loc;
        c.cap = vectorExpr("the cap point");
        comma("cap point");
        loc = current_.loc;
        c.capRadius = floatExpr("the cap radius");
        if (c.capRadius < 0) error(loc, "cone radius must not be negative");
        if (c.baseRadius <= 0 && c.capRadius <= 0) error(loc, "cone needs at least one positive radius");
        if (c.base == c.cap) {
            error(capLoc, "cone base and cap are the same point (zero-length axis)");
            c.cap = c.base + Vec3(0, 1, 0);
        }
        shape = c;
    } else if (w == "disc") {
        Disc d;
        d.center = vectorExpr("the centre <x, y, z>");
        comma("centre");
        const SourceLoc loc = current_.loc;
        d.normal = vectorExpr("the normal <x, y, z>");
        if (length(d.normal) == 0) {
            error(loc, "disc normal must not be a zero-length vector");
            d.normal = {0, 1, 0};
        }
        d.normal = normalize(d.normal);
        comma("normal");
        d.radius = positiveRadius("disc radius");
        if (match(TokenKind::Comma)) {
            const SourceLoc holeLoc = current_.loc;
            d.holeRadius = floatExpr("the hole radius");
            if (d.holeRadius < 0) error(holeLoc, "disc hole radius must not be negative");
        }
        shape = d;
    } else if (w == "torus") {
        Torus t;
        t.majorRadius = positiveRadius("torus major radius");
        comma("major radius");
        t.minorRadius = positiveRadius("torus minor radius");
        shape = t;
    } else if (w == "triangle" || w == "smooth_triangle") {
        Mesh m;
        meshTriangle(m, w == "smooth_triangle");
        shape = m;
    } else if (isAlgebraicWord(w)) {
        algebraicBody(keyword, po);
    } else if (w == "prism") {
        prismBody(keyword, po);
    } else if (w == "text") {
        textBody(po);
    } else if (isRevolutionWord(w)) {
        revolutionBody(keyword, po);
    } else if (w == "blob") {
        blobBody(keyword, po);
    } else if (w == "mesh") {
        Mesh m;
        while (checkWord("triangle") || checkWord("smooth_triangle")) {
            const bool smooth = current_.text == "smooth_triangle";
            advance();
            expect(TokenKind::LeftBrace, smooth ? "'{' after 'smooth_triangle'" : "'{' after 'triangle'");
            meshTriangle(m, smooth);
            expect(TokenKind::RightBrace, "'}' to close the triangle");
        }
        if (m.triangles.empty()) error(keyword.loc, "mesh has no triangles");
        shape = m;
    } else { // union, merge, difference, intersection
        Csg csg;
        csg.op = w == "merge"        ? Csg::Op::Merge
                 : w == "difference" ? Csg::Op::Difference
                 : w == "intersection" ? Csg::Op::Intersection
                                       : Csg::Op::Union;
        shape = std::move(csg);
    }
}

// triangle-body = vector "," vector "," vector
// smooth-triangle-body = vector "," vector "," vector "," vector "," vector "," vector  (corner, normal, ...)
void Parser::meshTriangle(Mesh& mesh, bool smooth) {
    Vec3 corners[3], normals[3];
    for (int i = 0; i < 3; ++i) {
        if (i > 0) expect(TokenKind::Comma, "',' between triangle corners");
        corners[i] = vectorExpr("a triangle corner <x, y, z>");
        if (smooth) {
            expect(TokenKind::Comma, "',' after the corner");
            const SourceLoc loc = current_.loc;
            normals[i] = vectorExpr("a corner normal <x, y, z>");
            if (length(normals[i]) == 0) {
                error(loc, "smooth_triangle normal must not be a zero-length vector");
                normals[i] = {0, 1, 0};
            }
        }
    }
    const int base = static_cast<int>(mesh.vertices.size());
    for (const Vec3& c : corners) mesh.vertices.push_back(c);
    mesh.triangles.push_back({base, base + 1, base + 2});
    // Normals are per triangle once any triangle has them: flat triangles in a
    // mixed mesh get their face normal at all three corners.
    const bool hadNormals = !mesh.normalIndices.empty();
    if (smooth && !hadNormals) {
        for (size_t t = 0; t + 1 < mesh.triangles.size(); ++t) {
            const auto& tri = mesh.triangles[t];
            Vec3 n = cross(mesh.vertices[tri[1]] - mesh.vertices[tri[0]], mesh.vertices[tri[2]] - mesh.vertices[tri[0]]);
            if (length(n) > 0) n = normalize(n);
            const int ni = static_cast<int>(mesh.normals.size());
            mesh.normals.push_back(n);
            mesh.normalIndices.push_back({ni, ni, ni});
        }
    }
    if (smooth || hadNormals) {
        const int ni = static_cast<int>(mesh.normals.size());
        if (smooth) {
            for (const Vec3& n : normals) mesh.normals.push_back(normalize(n));
            mesh.normalIndices.push_back({ni, ni + 1, ni + 2});
        } else {
            Vec3 n = cross(corners[1] - corners[0], corners[2] - corners[0]);
            if (length(n) > 0) n = normalize(n);
            mesh.normals.push_back(n);
            mesh.normalIndices.push_back({ni, ni, ni});
        }
    }
}

void Parser::objectModifiers(ParsedObject& po, const Token& keyword) {
    int textures = 0; // a second `texture` is a layer on top of the first (POV-Ray)
    while (!match(TokenKind::RightBrace)) {
        if (isCsg(po) && atObjectWord()) {
            addChild(po, object());
            continue;
        }
        if (checkWord("texture") && textures++ > 0) {
            Texture layered = po.object.texture;
            layerTexture(layered, current_.loc);
            setTexture(po, layered);
            continue;
        }
        if (objectModifier(po)) continue;
        const bool sceneLevel = checkWord("camera") || checkWord("light_source") || checkWord("background") ||
                                checkWord("global_settings") || checkWord("render") || check(TokenKind::Directive);
        if (check(TokenKind::Identifier) && !sceneLevel) {
            std::vector<std::string> known = modifierWords();
            if (isCsg(po)) known.insert(known.end(), objectWords().begin(), objectWords().end());
            failUnknown(current_, known);
        }
        failExpected(("an object modifier or '}' to close '" + keyword.text + "'").c_str());
    }
    if (isCsg(po) && po.children.empty()) error(keyword.loc, keyword.text + " has no objects");
}

bool Parser::objectModifier(ParsedObject& po) {
    const SourceLoc loc = current_.loc;
    if (std::optional<Transform> t = transformItem()) {
        applyTransform(po, *t, loc);
        return true;
    }
    if (!check(TokenKind::Identifier)) return false;
    const std::string w = current_.text;
    Object& o = po.object;
    if (w == "texture") {
        setTexture(po, texture());
    } else if (w == "pigment") { // pigment, finish, normal: of the top layer (as POV-Ray)
        Texture t = o.texture;
        (t.layersAbove.empty() ? t : t.layersAbove.back()).pigment = pigment();
        setTexture(po, t);
    } else if (w == "finish") {
        Texture t = o.texture;
        (t.layersAbove.empty() ? t : t.layersAbove.back()).finish = finish();
        setTexture(po, t);
    } else if (w == "normal") {
        Texture t = o.texture;
        (t.layersAbove.empty() ? t : t.layersAbove.back()).normal = normal();
        setTexture(po, t);
    } else if (w == "interior") {
        o.interior = interior();
        Interior local = o.interior; // in this CSG's own space, as inherited textures
        transformInteriorSpaces(local, o.transform.inverted());
        for (ParsedObject& child : po.children) child.object.interior = local;
    } else if (w == "no_shadow") {
        advance();
        o.noShadow = true;
    } else if (w == "hollow") {
        advance();
        o.hollow = booleanOr(true);
    } else if (w == "inverse") {
        advance();
        o.inverse = !o.inverse;
    } else if (w == "motion") {
        motion(o);
    } else if (w == "clipped_by") {
        clippedBy(o);
    } else if (w == "open") {
        advance();
        if (Cylinder* c = std::get_if<Cylinder>(&o.shape)) c->open = true;
        else if (Cone* c = std::get_if<Cone>(&o.shape)) c->open = true;
        else if (Extrusion* e = std::get_if<Extrusion>(&o.shape); e && e->prism) e->open = true;
        else if (Revolution* r = std::get_if<Revolution>(&o.shape); r && r->kind == Revolution::Kind::Sor)
            r->open = true;
        else error(loc, "'open' applies only to cylinder, cone and prism, and to sor");
    } else {
        return false;
    }
    return true;
}

// motion = "motion" "{" [ "spline" ] ( key_items | { "at" float key_items } ) "}"
// key_items = { ("translate" | "rotate" | "scale") vector3 }   (each at most once per key)
// Without `at` the items are one key at time 1; keyed or not, the path starts
// from the identity at time 0 unless a key is given there (scene/motion.h).
void Parser::motion(Object& object) { object.motion.push_back(MotionStage{motionBlock(), Transform()}); }

Motion Parser::motionBlock() {
    advance();
    expect(TokenKind::LeftBrace, "'{' after 'motion'");
    Motion m;
    bool keyed = false;
    bool seen[3] = {false, false, false};
    const auto startKey = [&](double time) {
        m.keys.push_back(MotionKey{time});
        seen[0] = seen[1] = seen[2] = false;
    };
    while (!match(TokenKind::RightBrace)) {
        if (!check(TokenKind::Identifier)) failExpected("'at', 'translate', 'rotate', 'scale', 'spline' or '}' in motion");
        const Token word = current_;
        if (word.text == "spline") {
            advance();
            if (m.spline) error(word.loc, "'spline' given twice in motion");
            m.spline = true;
            continue;
        }
        if (word.text == "at") {
            advance();
            if (!keyed && !m.keys.empty()) error(word.loc, "'at' after key items without a time; begin with 'at'");
            keyed = true;
            const SourceLoc loc = current_.loc;
            const double time = floatExpr("a time");
            if (!(time >= 0 && time <= 1)) error(loc, "motion key times must be in [0, 1]");
            else if (!m.keys.empty() && !(time > m.keys.back().time)) error(loc, "motion key times must increase");
            startKey(time);
            continue;
        }
        const int index = word.text == "translate" ? 0 : word.text == "rotate" ? 1 : word.text == "scale" ? 2 : -1;
        if (index < 0) failUnknown(word, {"at", "translate", "rotate", "scale", "spline"});
        advance();
        if (m.keys.empty()) startKey(1);
        if (seen[index]) error(word.loc, "'" + word.text + "' given twice in " + (keyed ? "one motion key" : "motion"));
        seen[index] = true;
        const SourceLoc loc = current_.loc;
        const Vec3 v = vectorExpr();
        MotionKey& key = m.keys.back();
        if (index == 0) key.translate = v;
        else if (index == 1) key.rotate = v;
        else if (v.x == 0 || v.y == 0 || v.z == 0) error(loc, "motion scale has a zero component");
        else key.scale = v;
    }
    if (m.keys.empty()) m.keys.push_back(MotionKey{1});
    if (m.keys.front().time > 0) m.keys.insert(m.keys.begin(), MotionKey{0});
    return m;
}

// clipped_by = "clipped_by" "{" object { object } "}". The clips are kept in
// the object's parent space: the object's own transforms so far do not move
// them, those written after this block do (applyTransform).
void Parser::clippedBy(Object& clipped) {
    const SourceLoc loc = current_.loc;
    if (!clipped.motion.empty()) error(loc, "clipped_by after 'motion' is not supported; put it before the motion");
    advance();
    expect(TokenKind::LeftBrace, "'{' after 'clipped_by'");
    size_t count = 0;
    while (!match(TokenKind::RightBrace)) {
        if (!atObjectWord()) failExpected("an object or '}' in clipped_by");
        ParsedObject po = object();
        Object clip = std::move(po.object);
        if (!clip.motion.empty()) error(clip.loc, "'motion' on a clipped_by object is not supported");
        if (isCsg(po)) std::get<Csg>(clip.shape).children = csgChildren(po, clip.transform);
        clipped.clippedBy.push_back(std::move(clip));
        ++count;
    }
    if (count == 0) error(loc, "clipped_by needs at least one object");
}

// A transform goes after everything written so far, motions included
// (scene/motion.h). Textures and interiors are placed in the rest pose, so
// every transform moves them; clips are folded into the rest pose when the
// object reaches the scene (flatten), so only transforms before a motion move
// them here.
void Parser::applyTransform(ParsedObject& po, const Transform& t, const SourceLoc&) {
    Object& o = po.object;
    if (o.motion.empty())
        for (Object& clip : o.clippedBy) clip.transform = clip.transform.then(t);
    appendTransform(o.transform, o.motion, t);
    transformTextureSpaces(o.texture, t);
    transformInteriorSpaces(o.interior, t);
}

static void inheritTexture(ParsedObject& po, const Texture& texture) {
    if (po.textured) return;
    po.object.texture = texture;
    if (po.children.empty()) return;
    Texture local = texture; // in this CSG's own space
    transformTextureSpaces(local, po.object.transform.inverted());
    for (ParsedObject& child : po.children) inheritTexture(child, local);
}

// A texture on a union goes to its children that have none (POV-Ray).
void Parser::setTexture(ParsedObject& po, const Texture& texture) {
    po.textured = false; // a new texture replaces the object's own one
    inheritTexture(po, texture);
    po.textured = true;
}

void Parser::addChild(ParsedObject& parent, ParsedObject child) {
    if (parent.textured) {
        Texture local = parent.object.texture;
        transformTextureSpaces(local, parent.object.transform.inverted());
        inheritTexture(child, local);
    }
    parent.children.push_back(std::move(child));
}

void Parser::addObjectToScene(ParsedObject po) {
    flatten(po, Transform{}, MotionChain{}, false, false);
}

// A union reaches the scene as its leaves, each carrying the union's
// transforms and motions after its own (scene/motion.h appendPlacement): the
// same surfaces as the union itself, moving as it does. `parentBefore` and
// `parentChain` place the enclosing union in the world.
void Parser::flatten(ParsedObject& po, const Transform& parentBefore, const MotionChain& parentChain,
                     bool noShadow, bool hollow, const std::vector<Object>& parentClips) {
    Object& o = po.object;
    Transform before = o.transform;
    MotionChain chain = o.motion;
    appendPlacement(before, chain, parentBefore, parentChain);
    const Transform parentRest = restPlacement(parentBefore, parentChain);
    noShadow = noShadow || o.noShadow;
    hollow = hollow || o.hollow;
    // Clips go to the rest pose's world; an enclosing union's clips apply to every leaf.
    std::vector<Object> clips = parentClips;
    const Transform clipToRest = restPlacement(Transform{}, o.motion).then(parentRest);
    for (Object& clip : o.clippedBy) {
        clip.transform = clip.transform.then(clipToRest);
        clips.push_back(std::move(clip));
    }
    o.clippedBy.clear();
    if (isSolidCsg(po)) {
        std::get<Csg>(o.shape).children = csgChildren(po, restPlacement(before, chain));
    } else if (isCsg(po)) {
        for (ParsedObject& child : po.children) flatten(child, before, chain, noShadow, hollow, clips);
        return;
    }
    o.transform = before;
    o.motion = std::move(chain);
    transformTextureSpaces(o.texture, parentRest);
    transformInteriorSpaces(o.interior, parentRest);
    o.noShadow = noShadow;
    o.hollow = hollow;
    o.clippedBy = std::move(clips);
    scene_.objects.push_back(std::move(o));
}

// The children of a merge, difference or intersection as scene objects: each
// keeps its transform relative to the CSG (the accelerator composes them),
// while pigments map all the way to world space like every pigment in the model.
std::vector<Object> Parser::csgChildren(ParsedObject& po, const Transform& csgToWorld) {
    std::vector<Object> children;
    for (ParsedObject& child : po.children) {
        Object o = std::move(child.object);
        if (!o.motion.empty()) error(o.loc, "'motion' inside merge, difference or intersection is not supported");
        transformTextureSpaces(o.texture, csgToWorld);
        transformInteriorSpaces(o.interior, csgToWorld);
        if (isCsg(child)) std::get<Csg>(o.shape).children = csgChildren(child, o.transform.then(csgToWorld));
        children.push_back(std::move(o));
    }
    return children;
}

} // namespace drt
