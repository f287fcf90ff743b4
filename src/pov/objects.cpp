// Objects: the primitives the scene model has, meshes, CSG, `object { Name }`
// and the object modifiers. Unsupported shapes are skipped with a warning.
#include "pov/parser.h"
#include "scene/bounds.h"

#include <fmt/format.h>

namespace drt::pov {

using Kind = PovValue::Kind;

namespace {

const std::set<std::string>& primitiveWords() {
    static const std::set<std::string> w = {"sphere", "box", "plane", "cylinder", "cone", "disc", "torus",
                                            "triangle", "smooth_triangle", "mesh", "mesh2", "union", "merge",
                                            "difference", "intersection", "object", "polygon",
                                            "quadric", "cubic", "quartic", "poly", "superellipsoid", "prism", "text",
                                            "lathe", "sor", "height_field", "blob"};
    return w;
}

const std::set<std::string>& unsupportedShapes() {
    static const std::set<std::string> w = {"isosurface", "julia_fractal",
                                            "parametric", "sphere_sweep", "bicubic_patch", "ovus"};
    return w;
}

void transformLight(Light& l, const Transform& t) {
    l.position = t.point(l.position);
    l.pointAt = t.point(l.pointAt);
    if (l.area) {
        l.area->axis1 = t.vector(l.area->axis1);
        l.area->axis2 = t.vector(l.area->axis2);
    }
}

void transformPigments(PovObject& o, const Transform& t) {
    transformTextureSpaces(o.object.texture, t);
    transformInteriorSpaces(o.object.interior, t);
    for (PovObject& c : o.children) transformPigments(c, t);
}

void inheritTexture(PovObject& o, const Texture& tex) {
    if (o.textured) return;
    o.object.texture = tex;
    for (PovObject& c : o.children) inheritTexture(c, tex);
}

void inheritInterior(PovObject& o, const Interior& in) {
    if (o.interiorSet) return;
    o.object.interior = in;
    for (PovObject& c : o.children) inheritInterior(c, in);
}

void setTexture(PovObject& o, const Texture& tex) {
    o.textured = false;
    inheritTexture(o, tex);
    o.textured = true;
}

void setInterior(PovObject& o, const Interior& in) {
    o.interiorSet = false;
    inheritInterior(o, in);
    o.interiorSet = true;
}

} // namespace

void objectBounds(const PovObject& po, Vec3& lower, Vec3& upper) { drt::objectBounds(toObject(po), lower, upper); }

bool PovParser::isObjectWord(const Tok& t) const {
    return t.kind == TokKind::Word && !lookup(t.text) &&
           (primitiveWords().count(t.text) || unsupportedShapes().count(t.text));
}

// After a motion, a transform goes after it (scene/motion.h); clips and
// textures take every transform (they are placed in the rest pose).
void PovParser::applyTransform(PovObject& o, const Transform& t) {
    appendTransform(o.object.transform, o.object.motion, t);
    for (Object& clip : o.object.clippedBy) clip.transform = clip.transform.then(t);
    transformPigments(o, t);
    for (Light& l : o.lights) transformLight(l, t);
}

namespace {

Mesh singleTriangle(const Vec3& a, const Vec3& b, const Vec3& c) {
    Mesh m;
    m.vertices = {a, b, c};
    m.triangles = {{0, 1, 2}};
    return m;
}

} // namespace

PovObject PovParser::object(const Tok& keyword) {
    DepthGuard guard(*this, keyword.loc);
    const std::string& w = keyword.text;
    PovObject po;
    po.object.loc = keyword.loc;
    po.object.texture = defaultTexture_;
    if (w == "light_source") {
        std::optional<PovObject> looksLike;
        const Light light = lightSource(keyword.loc, &looksLike);
        if (looksLike) po = std::move(*looksLike); // the shape carries the light
        else po.lightOnly = true;
        po.lights.push_back(light);
        return po;
    }
    const Tok open = expectSymbol("{", ("after '" + w + "'").c_str());
    if (unsupportedShapes().count(w)) {
        warnOnce("shape-" + w, keyword.loc, "'" + w + "' is not supported; the object is left out");
        skipBlock();
        po.lightOnly = true; // nothing to render
        return po;
    }
    Object& o = po.object;
    auto comma = [&]() { acceptSymbol(","); };
    if (w == "sphere") {
        Sphere s;
        s.center = vectorExpr();
        comma();
        s.radius = floatExpr();
        o.shape = s;
    } else if (w == "box") {
        Box b;
        b.corner1 = vectorExpr();
        comma();
        b.corner2 = vectorExpr();
        o.shape = b;
    } else if (w == "plane") {
        Plane p;
        const SourceLoc at = peek().loc;
        const Vec3 n = vectorExpr();
        comma();
        const double d = floatExpr();
        // POV-Ray divides both by |normal|: plane { <0,2,0>, 1 } is y = 0.5.
        const double len = length(n);
        if (!(len > 1e-10)) fail(at, "plane normal is a zero vector");
        p.normal = n / len;
        p.distance = d / len;
        o.shape = p;
    } else if (w == "cylinder") {
        Cylinder c;
        c.base = vectorExpr();
        comma();
        c.cap = vectorExpr();
        comma();
        c.radius = floatExpr();
        o.shape = c;
    } else if (w == "cone") {
        Cone c;
        c.base = vectorExpr();
        comma();
        c.baseRadius = floatExpr();
        comma();
        c.cap = vectorExpr();
        comma();
        c.capRadius = floatExpr();
        o.shape = c;
    } else if (w == "disc") {
        Disc d;
        d.center = vectorExpr();
        comma();
        d.normal = vectorExpr();
        comma();
        d.radius = floatExpr();
        if (acceptSymbol(",")) d.holeRadius = floatExpr();
        o.shape = d;
    } else if (w == "torus") {
        Torus t;
        t.majorRadius = floatExpr();
        comma();
        t.minorRadius = floatExpr();
        o.shape = t;
    } else if (isAlgebraicWord(w)) {
        o.shape = algebraicShape(keyword);
    } else if (w == "triangle") {
        const Vec3 a = vectorExpr();
        comma();
        const Vec3 b = vectorExpr();
        comma();
        const Vec3 c = vectorExpr();
        o.shape = singleTriangle(a, b, c);
    } else if (w == "smooth_triangle") {
        Vec3 p[3], n[3];
        for (int i = 0; i < 3; ++i) {
            if (i) comma();
            p[i] = vectorExpr();
            comma();
            n[i] = vectorExpr();
        }
        Mesh m = singleTriangle(p[0], p[1], p[2]);
        m.normals = {n[0], n[1], n[2]};
        m.normalIndices = {{0, 1, 2}};
        o.shape = m;
    } else if (w == "prism") {
        o.shape = prismShape(keyword.loc);
    } else if (w == "lathe" || w == "sor") {
        o.shape = revolutionShape(keyword);
    } else if (w == "blob") {
        o.shape = blobShape(keyword);
    } else if (w == "height_field") {
        std::optional<Mesh> field = heightFieldShape(keyword.loc);
        if (field) o.shape = std::move(*field);
        else po.lightOnly = true; // left out
    } else if (w == "text") {
        std::optional<Extrusion> text = textShape();
        if (text) o.shape = std::move(*text);
        else po.lightOnly = true; // an internal font: left out
    } else if (w == "polygon") {
        // polygon { n, p1, ..., pn }: a closed outline; drt triangulates it as a fan,
        // which is right for convex polygons.
        const int n = countExpr("polygon point count", 0, double(diags_.limits().meshTriangles));
        std::vector<Vec3> pts;
        for (int i = 0; i < n; ++i) {
            comma();
            pts.push_back(vectorExpr());
        }
        if (pts.size() >= 2 && pts.front() == pts.back()) pts.pop_back();
        warnOnce("polygon", keyword.loc, "polygon is triangulated as a fan (exact only for a convex outline)");
        Mesh m;
        m.vertices = pts;
        for (int i = 1; i + 1 < int(pts.size()); ++i) m.triangles.push_back({0, i, i + 1});
        if (m.triangles.empty()) fail(keyword.loc, "polygon needs at least 3 points");
        o.shape = m;
    } else if (w == "mesh") {
        Mesh m;
        for (;;) {
            const Tok t = peek();
            if (!(t.isWord("triangle") || t.isWord("smooth_triangle"))) break;
            next();
            expectSymbol("{", "after 'triangle'");
            const bool smooth = t.text == "smooth_triangle";
            const int base = int(m.vertices.size());
            Vec3 normals[3];
            for (int i = 0; i < 3; ++i) {
                if (i) comma();
                m.vertices.push_back(vectorExpr());
                if (smooth) {
                    comma();
                    normals[i] = vectorExpr();
                }
            }
            m.triangles.push_back({base, base + 1, base + 2});
            if (smooth) {
                const int nb = int(m.normals.size());
                m.normals.insert(m.normals.end(), normals, normals + 3);
                while (m.normalIndices.size() + 1 < m.triangles.size()) m.normalIndices.push_back({-1, -1, -1});
                m.normalIndices.push_back({nb, nb + 1, nb + 2});
            }
            while (!acceptSymbol("}")) {
                const Tok s = next();
                if (s.isWord("texture")) {
                    warnOnce("mesh-texture", s.loc, "per-triangle textures in a mesh are not supported; ignored");
                    texture(Texture{});
                } else {
                    failExpected(s, "'texture' or '}' in a mesh triangle");
                }
            }
        }
        if (!m.normalIndices.empty()) {
            // Flat triangles in a smooth mesh: use their face normal at each corner.
            while (m.normalIndices.size() < m.triangles.size()) m.normalIndices.push_back({-1, -1, -1});
            for (size_t i = 0; i < m.triangles.size(); ++i) {
                if (m.normalIndices[i][0] >= 0) continue;
                const auto& tri = m.triangles[i];
                const Vec3 n = cross(m.vertices[size_t(tri[1])] - m.vertices[size_t(tri[0])],
                                     m.vertices[size_t(tri[2])] - m.vertices[size_t(tri[0])]);
                const int nb = int(m.normals.size());
                m.normals.push_back(n);
                m.normalIndices[i] = {nb, nb, nb};
            }
        }
        if (m.triangles.empty()) fail(keyword.loc, "mesh has no triangles");
        o.shape = m;
    } else if (w == "mesh2") {
        Mesh m;
        auto vectorList = [&](std::vector<Vec3>& out) {
            expectSymbol("{", "");
            const int n = countExpr("mesh2 vector count", 0, double(diags_.limits().meshTriangles));
            for (int i = 0; i < n; ++i) {
                comma();
                out.push_back(vectorExpr());
            }
            acceptSymbol(",");
            expectSymbol("}", "after the listed count of items");
        };
        auto indexList = [&](std::vector<std::array<int, 3>>& out, int maxIndex, const char* what) {
            expectSymbol("{", "");
            const int n = countExpr("mesh2 index count", 0, double(diags_.limits().meshTriangles));
            for (int i = 0; i < n; ++i) {
                comma();
                const SourceLoc at = peek().loc;
                const Vec3 v = vectorExpr();
                const std::string indexName = std::string(what) + " index";
                std::array<int, 3> tri{};
                for (int k = 0; k < 3; ++k)
                    tri[size_t(k)] = countValue(v[k], at, indexName.c_str(), 0, double(maxIndex) - 1);
                out.push_back(tri);
                // Optional texture indices after a face.
                while (peekOperator().is(",")) {
                    next();
                    if (peek().is("<") || peek().is("}")) {
                        pushBack(Tok{TokKind::Symbol, ",", 0, at});
                        break;
                    }
                    floatExpr();
                }
            }
            acceptSymbol(",");
            expectSymbol("}", "after the listed count of items");
        };
        for (;;) {
            const Tok t = peek();
            if (t.isWord("vertex_vectors")) next(), vectorList(m.vertices);
            else if (t.isWord("normal_vectors")) next(), vectorList(m.normals);
            else if (t.isWord("face_indices")) next(), indexList(m.triangles, int(m.vertices.size()), "vertex");
            else if (t.isWord("normal_indices")) next(), indexList(m.normalIndices, int(m.normals.size()), "normal");
            else if (t.isWord("uv_vectors") || t.isWord("uv_indices") || t.isWord("texture_list")) {
                next();
                if (t.text == "texture_list")
                    warnOnce("mesh-texture", t.loc, "per-triangle textures in a mesh are not supported; ignored");
                expectSymbol("{", "");
                skipBlock();
            } else break;
        }
        if (m.triangles.empty()) fail(keyword.loc, "mesh2 has no face_indices");
        if (!m.normals.empty() && m.normalIndices.empty()) {
            // Without normal_indices, normals pair with vertices one to one.
            if (m.normals.size() != m.vertices.size())
                fail(keyword.loc, "mesh2: normal_vectors needs normal_indices or one normal per vertex");
            m.normalIndices = m.triangles;
        }
        if (!m.normalIndices.empty() && m.normalIndices.size() != m.triangles.size())
            fail(keyword.loc, "mesh2: normal_indices and face_indices have different counts");
        o.shape = m;
    } else if (w == "union" || w == "merge" || w == "difference" || w == "intersection") {
        Csg csg;
        csg.op = w == "union" ? Csg::Op::Union : w == "merge" ? Csg::Op::Merge
                 : w == "difference" ? Csg::Op::Difference : Csg::Op::Intersection;
        o.shape = csg;
        for (;;) {
            const Tok t = peek();
            if (!(isObjectWord(t) || t.isWord("light_source"))) break;
            next();
            PovObject child = object(t);
            if (!o.transform.isIdentity()) {
                // Transforms before the children: bring the child's pigments and
                // lights into the union's output space.
                transformPigments(child, o.transform);
                for (Light& l : child.lights) transformLight(l, o.transform);
            }
            po.lights.insert(po.lights.end(), child.lights.begin(), child.lights.end());
            if (child.lightOnly) continue;
            child.lights.clear();
            if (po.textured) inheritTexture(child, o.texture);
            if (po.interiorSet) inheritInterior(child, o.interior);
            po.children.push_back(std::move(child));
        }
    } else if (w == "object") {
        const Tok t = next();
        const Cell c = t.kind == TokKind::Word ? useIndexed(t) : nullptr;
        if (c && c->kind == Kind::Object) {
            po = *c->object;
            po.object.loc = keyword.loc;
        } else if (isObjectWord(t) || t.isWord("light_source")) {
            po = object(t);
        } else if (t.kind == TokKind::Word && !c) {
            fail(t.loc, "undeclared object identifier '" + t.text + "'");
        } else {
            failExpected(t, "an object identifier or an object");
        }
    }
    // ---- modifiers
    int textures = 0;
    std::vector<Object> boundedBy; // for `clipped_by { bounded_by }`
    for (;;) {
        const Tok t = peek();
        if (t.is("}")) {
            next();
            break;
        }
        if (std::optional<Transform> tr = transformItem()) {
            applyTransform(po, *tr);
            for (Object& b : boundedBy) b.transform = b.transform.then(*tr);
            continue;
        }
        next();
        if (t.kind != TokKind::Word) failExpected(t, "an object modifier or '}'");
        const std::string& m = t.text;
        const Cell c = lookup(m);
        if (c && (c->kind == Kind::Texture || c->kind == Kind::Pigment || c->kind == Kind::Finish ||
                  c->kind == Kind::Interior || c->kind == Kind::Material)) {
            fail(t.loc, std::string("a ") + kindName(c->kind) + " identifier must be wrapped: " + kindName(c->kind) +
                            " { " + m + " }");
        }
        if (m == "motion") { // drt's motion blur (pov/motion.cpp)
            o.motion.push_back(MotionStage{motionBlock(), Transform()});
            continue;
        }
        if (m == "texture") {
            if (++textures > 1) { // `texture {A} texture {B}`: B is a layer on top of A
                Texture layered = o.texture;
                layerOnTop(layered, texture(defaultTexture_), t.loc);
                setTexture(po, layered);
                continue;
            }
            setTexture(po, texture(po.textured ? o.texture : defaultTexture_));
        } else if (m == "pigment") { // pigment, finish, normal: of the top layer (measured against POV-Ray)
            Texture tex = po.textured ? o.texture : defaultTexture_;
            Texture& top = tex.layersAbove.empty() ? tex : tex.layersAbove.back();
            top.pigment = pigment(top.pigment);
            setTexture(po, tex);
        } else if (m == "finish") {
            Texture tex = po.textured ? o.texture : defaultTexture_;
            Texture& top = tex.layersAbove.empty() ? tex : tex.layersAbove.back();
            top.finish = finish(top.finish);
            setTexture(po, tex);
        } else if (m == "normal") {
            if (std::optional<Normal> n = normalBlock(t.loc)) {
                Texture tex = po.textured ? o.texture : defaultTexture_;
                Texture& top = tex.layersAbove.empty() ? tex : tex.layersAbove.back();
                top.normal = std::move(n);
                setTexture(po, tex);
            }
        } else if (m == "interior") {
            setInterior(po, interior(o.interior));
        } else if (m == "material") {
            const PovMaterial mat = material(PovMaterial{});
            if (mat.texture) setTexture(po, *mat.texture);
            if (mat.interior) setInterior(po, *mat.interior);
        } else if (m == "hollow") {
            const Tok n = peekOperator();
            o.hollow = (n.kind == TokKind::Number || n.isWord("on") || n.isWord("off") || n.isWord("true") ||
                        n.isWord("false") || n.isWord("yes") || n.isWord("no"))
                           ? boolExpr()
                           : true;
        } else if (m == "no_shadow") {
            o.noShadow = true;
        } else if (m == "inverse") {
            o.inverse = !o.inverse;
        } else if (m == "open") {
            if (Cylinder* cy = std::get_if<Cylinder>(&o.shape)) cy->open = true;
            else if (Cone* co = std::get_if<Cone>(&o.shape)) co->open = true;
            else if (Extrusion* ex = std::get_if<Extrusion>(&o.shape); ex && ex->prism) ex->open = true;
            else if (Revolution* rv = std::get_if<Revolution>(&o.shape); rv && rv->kind == Revolution::Kind::Sor)
                rv->open = true;
            else warnOnce("open", t.loc, "'open' applies to cylinder, cone, prism and sor only; ignored");
        } else if (m == "sturm" || m == "smooth" || m == "split_union" || m == "hierarchy") {
            const Tok n = peekOperator();
            const bool on = n.kind == TokKind::Number ? floatExpr() != 0 : true;
            if (Algebraic* a = std::get_if<Algebraic>(&o.shape); a && m == "sturm" && a->form != Algebraic::Form::Quadric)
                a->sturm = on;
            if (Revolution* rv = std::get_if<Revolution>(&o.shape); rv && m == "sturm") rv->sturm = on;
            if (Blob* b = std::get_if<Blob>(&o.shape); b && m == "sturm") b->sturm = on;
            if (Blob* b = std::get_if<Blob>(&o.shape); b && m == "hierarchy") b->hierarchy = on;
        } else if (m == "inside_vector") {
            vectorExpr();
        } else if (m == "bounded_by" || m == "clipped_by") {
            // POV-Ray treats bounded_by as an optimisation (it can only cut an
            // object it does not enclose), so ignoring it is a note; the
            // objects are kept for `clipped_by { bounded_by }`.
            const std::optional<std::vector<Object>> objects = clipObjects(t);
            if (m == "bounded_by") {
                if (warned_.insert("note-bounded_by").second)
                    note(t.loc, "'bounded_by' is ignored: drt builds its own bounds");
                if (objects) boundedBy = *objects;
            } else if (!objects) {
                // `clipped_by { bounded_by }`: clip by the bounding objects.
                o.clippedBy.insert(o.clippedBy.end(), boundedBy.begin(), boundedBy.end());
            } else {
                o.clippedBy.insert(o.clippedBy.end(), objects->begin(), objects->end());
            }
        } else if (m == "photons" || m == "radiosity" || m == "interior_texture") {
            warnOnce(m, t.loc, "'" + m + "' is not supported and is ignored");
            expectSymbol("{", ("after '" + m + "'").c_str());
            skipBlock();
        } else if (m == "no_image" || m == "no_reflection" || m == "no_radiosity" || m == "double_illuminate" ||
                   m == "uv_mapping" || m == "cutaway_textures") {
            warnOnce(m, t.loc, "'" + m + "' is not supported and is ignored");
            const Tok n = peekOperator();
            if (n.kind == TokKind::Number || n.isWord("on") || n.isWord("off")) floatExpr();
        } else if (m == "light_source" && po.isCsg()) {
            warnOnce("light-after-modifier", t.loc, "light_source after the union's modifiers");
            Light l = lightSource(t.loc);
            transformLight(l, o.transform);
            po.lights.push_back(l);
        } else {
            failExpected(t, "an object modifier or '}'");
        }
    }
    if (po.isCsg() && po.children.empty() && !po.lights.empty()) po.lightOnly = true;
    if (po.isCsg() && po.children.empty() && po.lights.empty()) {
        // POV-Ray itself only warns and renders nothing for it: the image is the same.
        if (warned_.insert("note-empty-csg").second)
            note(keyword.loc, "'" + w + "' has no objects; left out (as POV-Ray)");
        po.lightOnly = true;
    }
    (void)open;
    return po;
}

// The objects of `bounded_by { ... }` or `clipped_by { ... }` in the space
// the enclosing object's transform maps to; nothing for `clipped_by {
// bounded_by }` and `bounded_by { clipped_by }` (the other block's objects).
// Unsupported shapes (already warned about) are left out.
std::optional<std::vector<Object>> PovParser::clipObjects(const Tok& word) {
    const std::string& keyword = word.text;
    expectSymbol("{", ("after '" + keyword + "'").c_str());
    std::vector<Object> objects;
    const char* other = keyword == "clipped_by" ? "bounded_by" : "clipped_by";
    bool any = false;
    for (;;) {
        const Tok t = next();
        if (t.is("}")) break;
        if (t.isWord(other) && !any) {
            expectSymbol("}", ("after '" + std::string(other) + "'").c_str());
            return std::nullopt;
        }
        if (!isObjectWord(t)) failExpected(t, "an object or '}' in " + keyword);
        any = true;
        PovObject clip = object(t);
        if (clip.lightOnly) continue;
        objects.push_back(toObject(clip));
    }
    if (!any) fail(word.loc, "'" + keyword + "' needs at least one object");
    return objects;
}

} // namespace drt::pov
