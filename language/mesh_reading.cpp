#include "language/mesh_reading.hpp"

#include <cmath>
#include <sstream>

#include "language/checked_integer.hpp"
#include "language/value_ops.hpp"

namespace hexant::language {

namespace {

using runtime::objects::MeshData;
using runtime::objects::MeshFace;

// The most vertices, normals, uvs or faces a mesh may have (indices are 32-bit).
constexpr long long kMaxMeshItems = 1LL << 31;

// A mesh's numbers must be finite, as a plain triangle's corners must: one
// infinite or NaN vertex made the whole mesh vanish with no word (issue
// 45; its bounds and hierarchy became NaN).
glm::dvec3 finite_vector(const glm::dvec3& p, const std::string& what) {
    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) return p;
    std::ostringstream text;
    text << what << " is not finite: <" << p.x << ", " << p.y << ", " << p.z << ">";
    throw ValueError(text.str());
}

glm::dvec3 fixed_vector(const runtime::Vector3Function& v, const std::string& what) {
    if (v.depends_on_time())
        throw ValueError(what +
                         " depends on clock; a mesh's triangles are fixed when the scene is "
                         "read (move, turn or deform the whole mesh with its transforms)");
    return finite_vector(v(0.0), what);
}

glm::dvec3 fixed_vector(const Value& v, const std::string& what) {
    return fixed_vector(to_vector3(v, what), what);
}

std::uint32_t add_vertex(MeshData& mesh, const glm::dvec3& p) {
    if (mesh.vertices.size() >= static_cast<std::size_t>(kMaxMeshItems))
        throw ValueError("the mesh has more than 2^31 vertices");
    mesh.vertices.push_back(p);
    return static_cast<std::uint32_t>(mesh.vertices.size() - 1);
}

void check_count(long long declared, std::size_t found, const std::string& section) {
    if (static_cast<std::size_t>(declared) != found)
        throw ValueError(section + " says it has " + std::to_string(declared) + " but lists " +
                         std::to_string(found));
}

void check_index(std::int32_t index, std::size_t size, const std::string& what, std::size_t face,
                 const std::string& of) {
    if (index >= 0 && static_cast<std::size_t>(index) >= size)
        throw ValueError("face " + std::to_string(face) + "'s " + what + " index " +
                         std::to_string(index) + " is beyond the " + std::to_string(size) + " " +
                         of);
}

}  // namespace

void add_mesh_triangle(MeshData& mesh, const runtime::ObjectRecord& triangle) {
    const auto* flat = std::get_if<runtime::Triangle>(&triangle.shape);
    const auto* smooth = std::get_if<runtime::SmoothTriangle>(&triangle.shape);
    if (!flat && !smooth)
        throw ValueError(std::string("a mesh holds triangles and smooth_triangles, not a ") +
                         runtime::shape_name(triangle.shape));
    if (!triangle.transform.empty())
        throw ValueError("a triangle in a mesh cannot be transformed (transform the mesh)");
    MeshFace face;
    const auto& points = flat ? flat->points : smooth->points;
    for (int i = 0; i < 3; ++i)
        face.vertex[i] = add_vertex(mesh, fixed_vector(points[i], "a mesh triangle's corner"));
    if (smooth)
        for (int i = 0; i < 3; ++i) {
            mesh.normals.push_back(fixed_vector(smooth->normals[i], "a mesh triangle's normal"));
            face.normal[i] = static_cast<std::int32_t>(mesh.normals.size() - 1);
        }
    // (POV-Ray's Parse_Three_UVCoords: without them the corners' uv are 0.)
    if (const auto& uv = flat ? flat->uv_vectors : smooth->uv_vectors)
        for (int i = 0; i < 3; ++i) {
            const auto& c = (*uv)[i].c;
            if (c[0].depends_on_time() || c[1].depends_on_time())
                throw ValueError(
                    "a mesh triangle's uv vector depends on clock; a mesh's triangles are fixed "
                    "when "
                    "the scene is read");
            finite_vector({c[0](0.0), c[1](0.0), 0.0}, "a mesh triangle's uv vector");
            mesh.uvs.emplace_back(c[0](0.0), c[1](0.0));
            face.uv[i] = static_cast<std::int32_t>(mesh.uvs.size() - 1);
        }
    if (triangle.texture) {
        mesh.textures.push_back(*triangle.texture);
        face.texture = static_cast<std::int32_t>(mesh.textures.size() - 1);
    }
    mesh.faces.push_back(face);
}

MeshValue mesh_value(const Value& value, const std::string& section) {
    MeshValue out;
    if (value.is<TimeFunction>()) {
        out.c[0] = to_constant(value, section + "'s value");
        return out;
    }
    if (!value.is<Vector>())
        throw ValueError(section + " holds numbers and vectors, not a " + type_name(value));
    const Vector& v = value.as<Vector>();
    if (v.size > 3)
        throw ValueError(section + " holds vectors of 2 or 3 numbers, not " +
                         std::to_string(v.size));
    out.size = v.size;
    for (int i = 0; i < v.size; ++i) {
        if (!v.c[i].is_constant())
            throw ValueError(
                section +
                "'s vector depends on clock; a mesh's triangles are fixed when the "
                "scene is read (move, turn or deform the whole mesh with its transforms)");
        out.c[i] = v.c[i].constant();
    }
    return out;
}

namespace {

glm::dvec3 vector3(const MeshValue& v) {
    if (v.size == 1) return glm::dvec3(v.c[0]);  // POV-Ray promotes a float
    return {v.c[0], v.c[1], v.size == 3 ? v.c[2] : 0.0};
}

std::array<std::int32_t, 3> index_triple(const MeshValue& v, const std::string& what) {
    if (v.size != 3) throw ValueError(what + " must be a vector <a, b, c>");
    std::array<std::int32_t, 3> out{};
    for (int i = 0; i < 3; ++i)
        out[i] = static_cast<std::int32_t>(checked_integer(v.c[i], what, 0, kMaxMeshItems - 1));
    return out;
}

long long mesh_count(const std::vector<MeshValue>& values, const std::string& section) {
    if (values.empty() || values[0].size != 1) throw ValueError(section + " needs its count first");
    return checked_integer(values[0].c[0], section + "'s count", 0, kMaxMeshItems);
}

}  // namespace

void read_mesh2_section(MeshData& mesh, const std::string& section,
                        const std::vector<MeshValue>& values) {
    const long long n = mesh_count(values, section);
    if (section == "vertex_vectors" || section == "normal_vectors") {
        check_count(n, values.size() - 1, section);
        auto& list = section == "vertex_vectors" ? mesh.vertices : mesh.normals;
        list.clear();
        list.reserve(values.size() - 1);
        for (std::size_t i = 1; i < values.size(); ++i)
            list.push_back(finite_vector(vector3(values[i]),
                                         "entry " + std::to_string(i - 1) + " of " + section));
        return;
    }
    if (section == "uv_vectors") {
        check_count(n, values.size() - 1, section);
        mesh.uvs.clear();
        mesh.uvs.reserve(values.size() - 1);
        for (std::size_t i = 1; i < values.size(); ++i) {
            const MeshValue& v = values[i];
            const glm::dvec2 uv(v.c[0], v.size == 1 ? v.c[0] : v.c[1]);
            finite_vector({uv.x, uv.y, 0.0}, "entry " + std::to_string(i - 1) + " of uv_vectors");
            mesh.uvs.push_back(uv);
        }
        return;
    }
    if (section == "face_indices") {
        // Each face: <a, b, c>, then none, one or three texture indices
        // (POV-Ray blends three; hexant takes the first).
        mesh.faces.clear();
        mesh.faces.reserve(static_cast<std::size_t>(n));
        for (std::size_t i = 1; i < values.size();) {
            if (values[i].size == 1)
                throw ValueError("face_indices expected a face <a, b, c> here");
            MeshFace face;
            const auto v = index_triple(values[i], "a face's vertex index");
            for (int k = 0; k < 3; ++k) face.vertex[k] = static_cast<std::uint32_t>(v[k]);
            ++i;
            int textures = 0;
            while (i < values.size() && values[i].size == 1) {
                const auto t =
                    checked_integer(values[i].c[0], "a face's texture index", 0, kMaxMeshItems - 1);
                if (textures == 0) face.texture = static_cast<std::int32_t>(t);
                ++textures;
                ++i;
            }
            if (textures != 0 && textures != 1 && textures != 3)
                throw ValueError("a face in face_indices takes one or three texture indices, not " +
                                 std::to_string(textures));
            mesh.faces.push_back(face);
        }
        check_count(n, mesh.faces.size(), section);
        return;
    }
    // normal_indices, uv_indices: one <a, b, c> per face, after face_indices.
    if (mesh.faces.empty()) throw ValueError(section + " must come after face_indices");
    check_count(n, values.size() - 1, section);
    if (values.size() - 1 != mesh.faces.size())
        throw ValueError(section + " has " + std::to_string(values.size() - 1) + " entries for " +
                         std::to_string(mesh.faces.size()) + " faces");
    for (std::size_t i = 1; i < values.size(); ++i) {
        const auto v = index_triple(
            values[i], section == "normal_indices" ? "a face's normal index" : "a face's uv index");
        (section == "normal_indices" ? mesh.faces[i - 1].normal : mesh.faces[i - 1].uv) = v;
    }
}

void read_mesh2_textures(MeshData& mesh, const std::vector<Value>& values) {
    if (values.empty()) throw ValueError("texture_list needs its count first");
    const long long n = checked_integer(to_constant(values[0], "texture_list's count"),
                                        "texture_list's count", 0, kMaxMeshItems);
    check_count(n, values.size() - 1, "texture_list");
    mesh.textures.clear();
    for (std::size_t i = 1; i < values.size(); ++i) {
        if (!values[i].is<runtime::Texture>()) throw ValueError("texture_list holds textures only");
        mesh.textures.push_back(values[i].as<runtime::Texture>());
    }
}

void set_inside_vector(MeshData& mesh, const Value& value) {
    const glm::dvec3 v = fixed_vector(value, "the mesh's inside_vector");
    if (!std::isfinite(v.x + v.y + v.z))
        throw ValueError("the mesh's inside_vector must be finite");
    // POV-Ray: a vector within EPSILON (1e-10) of zero leaves the mesh
    // without an inside.
    constexpr double kPovEpsilon = 1e-10;
    if (std::fabs(v.x) < kPovEpsilon && std::fabs(v.y) < kPovEpsilon &&
        std::fabs(v.z) < kPovEpsilon)
        mesh.inside_vector.reset();
    else
        mesh.inside_vector = v;
}

void finish_mesh(MeshData& mesh, const std::string& keyword) {
    if (mesh.faces.empty()) throw ValueError(keyword + " has no triangles");
    const bool mesh2 = keyword == "mesh2";
    mesh.mesh2 = mesh2;
    if (mesh2) {
        // POV-Ray's Parse_Mesh2: normals (uvs) without their indices serve
        // by the vertex indices only when there is one per vertex.
        const bool normal_indices = mesh.faces.front().normal[0] >= 0;
        const bool uv_indices = mesh.faces.front().uv[0] >= 0;
        if (!mesh.normals.empty() && !normal_indices && mesh.normals.size() != mesh.vertices.size())
            throw ValueError("mesh2 has " + std::to_string(mesh.normals.size()) +
                             " normal_vectors for " + std::to_string(mesh.vertices.size()) +
                             " vertex_vectors and no normal_indices section");
        if (!mesh.uvs.empty() && !uv_indices && mesh.uvs.size() != mesh.vertices.size())
            throw ValueError("mesh2 has " + std::to_string(mesh.uvs.size()) + " uv_vectors for " +
                             std::to_string(mesh.vertices.size()) +
                             " vertex_vectors and no uv_indices section");
    }
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        MeshFace& face = mesh.faces[f];
        for (int k = 0; k < 3; ++k)
            if (face.vertex[k] >= mesh.vertices.size())
                throw ValueError("face " + std::to_string(f) + "'s vertex index " +
                                 std::to_string(face.vertex[k]) + " is beyond the " +
                                 std::to_string(mesh.vertices.size()) + " vertex_vectors");
        // mesh2 without normal_indices (uv_indices): the vertex indices
        // index the normals (uvs) too. (A mesh's flat triangles have none.)
        if (mesh2 && !mesh.normals.empty() && face.normal[0] < 0)
            for (int k = 0; k < 3; ++k) face.normal[k] = static_cast<std::int32_t>(face.vertex[k]);
        if (mesh2 && !mesh.uvs.empty() && face.uv[0] < 0)
            for (int k = 0; k < 3; ++k) face.uv[k] = static_cast<std::int32_t>(face.vertex[k]);
        for (int k = 0; k < 3; ++k) {
            check_index(face.normal[k], mesh.normals.size(), "normal", f, "normal_vectors");
            check_index(face.uv[k], mesh.uvs.size(), "uv", f, "uv_vectors");
        }
        check_index(face.texture, mesh.textures.size(), "texture", f,
                    "textures of its texture_list");
        // POV-Ray: a face whose three normals are equal (squared
        // differences within EPSILON, 1e-10) is flat, lit by its own normal.
        if (face.smooth()) {
            const glm::dvec3 d1 = mesh.normals[face.normal[0]] - mesh.normals[face.normal[1]];
            const glm::dvec3 d2 = mesh.normals[face.normal[0]] - mesh.normals[face.normal[2]];
            if (glm::dot(d1, d1) <= 1e-10 && glm::dot(d2, d2) <= 1e-10) face.normal = {-1, -1, -1};
        }
    }
    mesh.build_hierarchy();
}

}  // namespace hexant::language
