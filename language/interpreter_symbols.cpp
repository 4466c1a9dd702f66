// The Interpreter's use of its symbols (the checks that need time and places), the merge of
// a time split's sides, and #include's reading of files. Part of the Interpreter
// (language/interpreter_state.hpp).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <regex>
#include <set>
#include <sstream>

#include "language/array_index.hpp"
#include "language/checked_integer.hpp"
#include "language/interpreter.hpp"
#include "language/interpreter_state.hpp"
#include "language/source_files.hpp"
#include "runtime/objects/parameter_check.hpp"

namespace hexant::language {

// ------------------------------------------------------------------ symbols

void Interpreter::check_declared(const std::string& name) const {
    const runtime::Lifetime* when = symbols.declared_when(name);
    if (when == nullptr || when->is_always()) return;
    for (const runtime::Interval& piece : domain.within(animation_time()))
        if (!when->holds_all(piece)) {
            // The first instant of the piece it does not hold.
            const runtime::Lifetime gaps = when->complement_within(piece);
            const double t = gaps.pieces().empty() ? piece.lo : gaps.pieces().front().lo;
            std::ostringstream message;
            message.precision(17);
            message << "'" << name << "' is not declared at clock " << t
                    << ": it is declared only on some pieces of time (under a branch on clock)";
            throw ValueError(message.str());
        }
}

namespace {

// What BlockStack::edit() does not count: the kind of
// shape and the transform (apply_transform edits the block directly). A
// side of a time split may change neither (not yet piecewise in time).
bool same_but_members(const runtime::ObjectRecord& a, const runtime::ObjectRecord& b,
                      bool texture_may_differ) {
    const auto* ca = std::get_if<runtime::Csg>(&a.shape);
    const auto* cb = std::get_if<runtime::Csg>(&b.shape);
    if (a.shape.index() != b.shape.index() || (ca && ca->kind != cb->kind)) return false;
    return a.transform.steps().size() == b.transform.steps().size() &&
           (texture_may_differ || a.texture.has_value() == b.texture.has_value()) &&
           a.interior.has_value() == b.interior.has_value() && a.no_shadow == b.no_shadow &&
           a.no_image == b.no_image && a.no_reflection == b.no_reflection &&
           a.no_radiosity == b.no_radiosity && a.photons == b.photons &&
           a.double_illuminate == b.double_illuminate && a.hollow == b.hollow &&
           a.inverse == b.inverse && a.limits == b.limits;
}

// The texture that is `when_true` where `c` holds and `when_false`
// elsewhere: a texture_map on a function pattern of time alone, exactly 1
// where c holds and 0 where it does not (POV-Ray's truth: not zero), so
// that its two entries are never blended.
runtime::Texture texture_by_condition(const TimeFunction& c, runtime::Texture when_true,
                                      runtime::Texture when_false) {
    const runtime::pattern::Kind* function = runtime::pattern::find_kind("function");
    if (function == nullptr) throw ValueError("the function pattern is missing");
    runtime::Texture t;
    t.patterned = runtime::pattern::Pattern::of(*function);
    const TimeFunction truth =
        TimeFunction::apply(runtime::TimeOp::Not, TimeFunction::apply(runtime::TimeOp::Not, c));
    t.patterned.edit().function = std::make_shared<const runtime::SpaceFunction>(truth);
    t.texture_map.push_back(
        {TimeFunction(0.0), std::make_shared<const runtime::Texture>(std::move(when_false))});
    t.texture_map.push_back(
        {TimeFunction(1.0), std::make_shared<const runtime::Texture>(std::move(when_true))});
    return t;
}

}  // namespace

void Interpreter::merge_time_sides(const p::position& at, const TimeFunction& c,
                                   std::optional<TimeSide> (&sides)[2],
                                   const std::optional<runtime::ObjectRecord>& top_before,
                                   const runtime::CameraRecord& camera_before,
                                   const runtime::ColourFunction& background_before) {
    try {
        // The camera: each side's on its own pieces, ahead of what held
        // before (which still holds outside this split's time).
        if ((sides[0] && sides[0]->camera) || (sides[1] && sides[1]->camera)) {
            runtime::CameraRecord merged = camera_before;
            std::vector<runtime::CameraRecord::Piece> fresh;
            for (const auto& s : sides) {
                if (!s) continue;
                const runtime::CameraRecord& camera = s->camera ? *s->camera : camera_before;
                for (const auto& piece : camera.pieces)
                    fresh.push_back({piece.when.intersect(s->when), piece.items});
                fresh.push_back({s->when, camera.items});
            }
            fresh.insert(fresh.end(), camera_before.pieces.begin(), camera_before.pieces.end());
            merged.pieces = std::move(fresh);
            scene.camera = std::move(merged);
            ++camera_sets;
        }
        // The background: `c ? one : other`, component by component.
        if ((sides[0] && sides[0]->background) || (sides[1] && sides[1]->background)) {
            runtime::ColourFunction colour[2];
            for (int side = 0; side < 2; ++side)
                colour[side] = sides[side] && sides[side]->background ? *sides[side]->background
                                                                      : background_before;
            if (!sides[1])
                scene.background = colour[0];
            else if (!sides[0])
                scene.background = colour[1];
            else
                for (int i = 0; i < 5; ++i)
                    scene.background.c[i] = TimeFunction::apply(runtime::TimeOp::Conditional, c,
                                                                colour[0].c[i], colour[1].c[i]);
            ++background_sets;
        }
        // The variables either side changed.
        std::map<SymbolTable::Key, bool> changed;
        for (const auto& s : sides)
            if (s)
                for (const auto& entry : s->after) changed[entry.first] = true;
        for (const auto& [key, unused] : changed) {
            (void)unused;
            const std::optional<SymbolTable::Held> before = symbols.held(key);
            std::optional<SymbolTable::Held> held[2];
            for (int side = 0; side < 2; ++side) {
                if (!sides[side]) continue;
                const auto found = sides[side]->after.find(key);
                held[side] = found != sides[side]->after.end() ? found->second : before;
            }
            std::optional<SymbolTable::Held> merged;
            if (!sides[1])
                merged = held[0];
            else if (!sides[0])
                merged = held[1];
            else if (held[0] || held[1]) {
                // Declared where either side has it, on that side's pieces.
                std::vector<runtime::Interval> declared;
                std::optional<Value> value[2];
                for (int side = 0; side < 2; ++side) {
                    if (!held[side]) continue;
                    value[side] = held[side]->value;
                    for (const auto& piece :
                         held[side]->defined.intersect(sides[side]->when).within(animation_time()))
                        declared.push_back(piece);
                }
                runtime::Lifetime defined = runtime::Lifetime::of(std::move(declared));
                if (defined.holds_all(animation_time())) defined = runtime::Lifetime::always();
                merged = SymbolTable::Held{*merge_sides("'" + key.second + "'", c, value[0],
                                                        sides[0]->when, value[1], sides[1]->when),
                                           std::move(defined)};
            }
            symbols.set_held(key, merged);
        }
        // The values they left (a macro's result): one each, side by side.
        if (sides[0] && sides[1] && sides[0]->pushed.size() != sides[1]->pushed.size())
            throw ValueError("the two sides of this clock-dependent branch give " +
                             std::to_string(sides[0]->pushed.size()) + " and " +
                             std::to_string(sides[1]->pushed.size()) +
                             " values; each side must give as many");
        const std::size_t count = sides[0]   ? sides[0]->pushed.size()
                                  : sides[1] ? sides[1]->pushed.size()
                                             : 0;
        for (std::size_t i = 0; i < count; ++i) {
            if (!sides[1])
                values.push(sides[0]->pushed[i]);
            else if (!sides[0])
                values.push(sides[1]->pushed[i]);
            else
                values.push(*merge_sides("the value this branch gives", c, sides[0]->pushed[i],
                                         sides[0]->when, sides[1]->pushed[i], sides[1]->when));
        }
        // The object around the branch: the CSG members and lights each side
        // added (each living on its side's pieces, finish_object), and
        // nothing else changed.
        if (top_before) {
            runtime::ObjectRecord merged = *top_before;
            auto* members = std::get_if<runtime::Csg>(&merged.shape);
            const std::size_t base_members =
                members ? std::get<runtime::Csg>(top_before->shape).children.size() : 0;
            bool texture_changed = false;
            for (const auto& s : sides) {
                if (!s || !s->top) continue;
                const bool texture_only = s->top_edited == BlockStack::Edited::TextureOnly;
                if (s->top_edited == BlockStack::Edited::Otherwise ||
                    !same_but_members(*s->top, *top_before, texture_only))
                    throw PiecewiseError(
                        "this clock-dependent branch changes the object around it "
                        "(a transform, interior or flag); hexant makes the CSG "
                        "members it adds and its texture piecewise in time, not yet "
                        "its other modifiers (put the branch in the value they use)");
                texture_changed = texture_changed || texture_only;
                if (const auto* csg = std::get_if<runtime::Csg>(&s->top->shape))
                    members->children.insert(
                        members->children.end(),
                        csg->children.begin() + static_cast<std::ptrdiff_t>(base_members),
                        csg->children.end());
                merged.lights.insert(
                    merged.lights.end(),
                    s->top->lights.begin() + static_cast<std::ptrdiff_t>(top_before->lights.size()),
                    s->top->lights.end());
            }
            // Its texture, where a side changed it: each side's (the
            // #default's where a side left the object without one).
            if (texture_changed) {
                const auto texture_of = [&](const std::optional<TimeSide>& s) {
                    const auto& record = s && s->top ? *s->top : *top_before;
                    return record.texture ? *record.texture : scene.default_texture;
                };
                merged.texture =
                    texture_by_condition(c, texture_of(sides[0]), texture_of(sides[1]));
            }
            blocks.top() = std::move(merged);
        }
    } catch (const ValueError& e) {
        fail(at, e);
    }
}

runtime::TruthPieces Interpreter::split_domain(const TimeFunction& c, const p::position& at) {
    runtime::TruthPieces pieces;
    try {
        pieces =
            runtime::split_by_truth(c, domain.within(animation_time()), options.limits.time_pieces);
    } catch (const runtime::LimitError& e) {
        if (dynamic_cast<const runtime::TimePiecesLimit*>(&e) != nullptr) split_refused = true;
        fail(at, e.what());
    }
    // (Reported where it does split: a #while on clock that holds from its
    // second turn on would list every turn.)
    if (!pieces.instants.empty())
        scene.time_splits.push_back({{at.source, at.line, at.column}, pieces.instants});
    return pieces;
}

void Interpreter::require_whole_time(const p::position& where, const char* what) const {
    if (domain.is_always()) return;
    fail_piecewise(where,
                   std::string(what) +
                       " is set under a branch whose condition depends on clock; hexant makes "
                       "objects, lights, floats and vectors piecewise in time, not yet this");
}

void Interpreter::assign_element(const std::string& name, const std::vector<Value>& indices,
                                 Value value, const p::position& where) {
    try {
        Array& array = symbols.array_for_element(name);
        std::vector<double> at;
        for (const auto& i : indices) at.push_back(to_constant(i, "an array index"));
        auto& slot = array.elements[element_index(array, at)];
        array.charge.add(element_bytes(value));
        if (slot) array.charge.remove(element_bytes(**slot));
        slot = std::make_shared<Value>(std::move(value));
    } catch (const ValueError& e) {
        fail(where, e);
    }
}

const char* const kPovRayIncludeDir = "/usr/share/povray-3.7/include";
const char* const kPovRayFontDir = "/usr/share/fonts/truetype/povray";

bool lies_in(const std::filesystem::path& file, const std::filesystem::path& folder) {
    auto f = file.begin();
    for (auto d = folder.begin(); d != folder.end(); ++d, ++f) {
        if (d->empty()) continue;  // a trailing separator
        if (f == file.end() || *f != *d) return false;
    }
    return true;
}

bool is_system_path(const std::filesystem::path& file) {
    for (const std::filesystem::path system : {"/proc", "/sys", "/dev"})
        if (lies_in(file, system)) return true;
    return false;
}

std::string read_source_text(const std::filesystem::path& path, std::size_t max_bytes) {
    namespace fs = std::filesystem;
    std::error_code error;
    // Not through a symbolic link's name: what it points at.
    if (!fs::is_regular_file(path, error))
        throw ValueError(fs::exists(path, error)
                             ? "it is not a regular file (a device, FIFO or folder cannot be read)"
                             : "it does not exist");
    const auto size = fs::file_size(path, error);
    if (error) throw ValueError("cannot read it: " + error.message());
    if (size > max_bytes)
        throw ValueError("its " + std::to_string(size) +
                         " bytes would take the scene's reading over its limit of text, " +
                         std::to_string(max_bytes) +
                         " bytes left (--max-text-read N raises the limit)");
    std::ifstream stream(path, std::ios::binary);
    if (!stream) throw ValueError("cannot read it");
    std::string text(size, '\0');
    stream.read(text.data(), static_cast<std::streamsize>(size));
    // A file that shrank while read keeps what was there; one that grew is
    // read up to the size checked.
    text.resize(static_cast<std::size_t>(stream.gcount()));
    return text;
}

std::string Interpreter::read_include(const std::filesystem::path& path, const p::position& where) {
    std::string text;
    try {
        text = read_source_text(
            path, options.limits.text_read - std::min(text_read_, options.limits.text_read));
    } catch (const ValueError& e) {
        fail(where, e, "include file '" + path.string() + "': ");
    }
    count_text(text.size(), where);
    return text;
}

std::filesystem::path Interpreter::resolve_include(
    const std::string& name, const p::position& where, const std::string& what,
    const std::vector<std::filesystem::path>& also) const {
    const FoundFile found = find_readable(name, what, also);
    if (!found.error.empty()) fail(where, found.error);
    if (std::find(scene.inputs.begin(), scene.inputs.end(), found.path) == scene.inputs.end())
        scene.inputs.push_back(found.path);
    return found.path;
}

Interpreter::FoundFile Interpreter::find_readable(
    const std::string& name, const std::string& what,
    const std::vector<std::filesystem::path>& also) const {
    namespace fs = std::filesystem;
    const fs::path file(name);
    std::vector<fs::path> folders{scene_folder_};
    folders.insert(folders.end(), options.include_paths.begin(), options.include_paths.end());
    folders.push_back(bundled_include_dir());
    // Last, POV-Ray's own (Debian's povray-includes): where `povray` finds
    // textures.inc or math.inc without a +L, as its povray.ini's
    // Library_Path says; a scene that includes them reads unchanged.
    folders.push_back(kPovRayIncludeDir);
    folders.insert(folders.end(), also.begin(), also.end());
    fs::path found;
    std::error_code error;
    if (file.is_absolute()) {
        if (fs::exists(file, error)) found = file;
    } else {
        for (const auto& folder : folders) {
            const fs::path candidate = folder / file;
            if (fs::exists(candidate, error)) {
                found = candidate;
                break;
            }
        }
    }
    if (found.empty()) {
        if (file.is_absolute()) return {{}, what + " '" + name + "' not found"};
        std::string searched;
        for (const auto& folder : folders)
            searched += (searched.empty() ? "" : ", ") + folder.string();
        return {{}, what + " '" + name + "' not found (searched " + searched + ")"};
    }
    // Confinement, on the file as it really is (`..` and symbolic links
    // resolved): a regular file inside a folder a scene may read. The
    // messages never show the file's contents.
    const fs::path real = fs::canonical(found, error);
    if (error) return {{}, what + " '" + name + "' cannot be read: " + error.message()};
    if (!fs::is_regular_file(real, error))
        return {{},
                what + " '" + name +
                    "' is not a regular file (a device, FIFO or folder "
                    "cannot be read)"};
    std::vector<fs::path> allowed = folders;
    allowed.push_back(kPovRayIncludeDir);
    allowed.insert(allowed.end(), options.read_paths.begin(), options.read_paths.end());
    if (is_system_path(real)) return {{}, what + " '" + name + "' is a system file: refused"};
    for (const auto& folder : allowed) {
        const fs::path root = fs::weakly_canonical(folder.empty() ? fs::path(".") : folder, error);
        if (!error && lies_in(real, root)) return {real, {}};
    }
    return {{},
            what + " '" + name +
                "' is outside the folders a scene may read (its own "
                "folder, the -L folders and the include folders; --allow-read DIR adds one)"};
}

}  // namespace hexant::language
