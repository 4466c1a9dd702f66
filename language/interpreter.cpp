// The reader's non-template parts: symbols, blocks, shapes, and the entry
// points that run the grammar over a scene file.
#include "language/interpreter.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>
#include <set>

#include "language/actions.hpp"
#include "language/checked_integer.hpp"
#include "language/interpreter_state.hpp"
#include "runtime/objects/parameter_check.hpp"

#ifndef HEXANT_BUNDLED_INCLUDE_DIR
#define HEXANT_BUNDLED_INCLUDE_DIR "language/include"
#endif

namespace hexant::language {

std::filesystem::path bundled_include_dir() { return HEXANT_BUNDLED_INCLUDE_DIR; }

Interpreter::Interpreter(const ParseOptions& options_in, runtime::SceneDescription& scene_in,
                         std::filesystem::path scene_folder)
    : scene(scene_in),
      options(options_in),
      scene_folder_(std::move(scene_folder)),
      array_memory_(std::make_shared<MemoryBudget>(options_in.limits.array_memory)) {
    scopes_.emplace_back();  // the global table
}

void Interpreter::check_string_length(std::size_t length, const std::string& what) const {
    if (length > options.limits.string_length)
        throw ValueError(what + " would be " + std::to_string(length) +
                         " characters long, more than the limit of " +
                         std::to_string(options.limits.string_length) +
                         " (--max-string-length N raises it)");
}

// ------------------------------------------------------------------ sources and errors

namespace {

// The newest source of that name (an include read twice is kept twice if
// its text changed in between).
const std::string* newest_source(const std::deque<std::pair<std::string, std::string>>& sources,
                                 const std::string& name) {
    for (auto it = sources.rbegin(); it != sources.rend(); ++it)
        if (it->first == name) return &it->second;
    return nullptr;
}

}  // namespace

const std::string& Interpreter::add_source(const std::string& name, std::string text) {
    // A file included again with the same text shares the kept copy (an
    // #include inside a loop kept one copy a turn). Macros declared in it
    // point into the copy, which is never changed.
    if (const std::string* kept = newest_source(sources_, name); kept != nullptr && *kept == text)
        return *kept;
    sources_.emplace_back(name, std::move(text));
    return sources_.back().second;
}

namespace {

// The line of `text` that starts at `begin`, without its end of line: up
// to a '\n', less a '\r' before it. A bare '\r' ends no line, as the
// reader counts lines (PEGTL's lf_crlf).
std::string_view line_from(const std::string& text, std::size_t begin) {
    std::size_t end = begin;
    while (end < text.size() && text[end] != '\n') ++end;
    if (end > begin && text[end - 1] == '\r') --end;
    return std::string_view(text).substr(begin, end - begin);
}

}  // namespace

ErrorPlace Interpreter::place(const p::position& position, std::string note) const {
    ErrorPlace place{position.source, position.line, position.column, {}, std::move(note)};
    if (const std::string* text = newest_source(sources_, position.source)) {
        std::size_t begin = std::min(position.byte, text->size());
        while (begin > 0 && (*text)[begin - 1] != '\n') --begin;
        place.set_source_line(line_from(*text, begin));
    }
    return place;
}

ErrorPlace Interpreter::place(const runtime::SourcePlace& where, std::string note) const {
    ErrorPlace place{where.file, where.line, where.column, {}, std::move(note)};
    if (const std::string* text = newest_source(sources_, where.file)) {
        // Found by its number: a record keeps its line, not its byte.
        std::size_t begin = 0;
        for (std::size_t line = 1; line < where.line && begin != std::string::npos; ++line) {
            begin = text->find('\n', begin);
            if (begin != std::string::npos) ++begin;
        }
        if (begin != std::string::npos) place.set_source_line(line_from(*text, begin));
    }
    return place;
}

SceneError Interpreter::to_scene_error(const p::parse_error& e) const {
    const auto& positions = e.positions();
    SceneError error(std::string(e.message()),
                     positions.empty() ? ErrorPlace{} : place(positions.front()));
    for (std::size_t i = 1; i < positions.size(); ++i) error.add_context(place(positions[i], "from here"));
    return error;
}

std::ostream& Interpreter::messages() const {
    return options.messages ? *options.messages : std::cerr;
}

void Interpreter::warn(const p::position& position, const std::string& message) {
    std::string text = position.source + ":" + std::to_string(position.line) + ":" +
                       std::to_string(position.column) + ": warning: " + message;
    messages() << text << "\n";
    scene.warnings.push_back(std::move(text));
}

// ------------------------------------------------------------------ stacks

Value Interpreter::pop() {
    if (stack_.empty()) throw std::logic_error("hexant: value stack underflow");
    Value v = std::move(stack_.back());
    stack_.pop_back();
    return v;
}

Value& Interpreter::top() {
    if (stack_.empty()) throw std::logic_error("hexant: value stack underflow");
    return stack_.back();
}

std::vector<Value> Interpreter::close_frame() {
    if (frames_.empty()) throw std::logic_error("hexant: frame stack underflow");
    const std::size_t begin = frames_.back();
    frames_.pop_back();
    std::vector<Value> values(std::make_move_iterator(stack_.begin() + static_cast<std::ptrdiff_t>(begin)),
                              std::make_move_iterator(stack_.end()));
    stack_.resize(begin);
    return values;
}

std::string Interpreter::pop_name() {
    if (names_.empty()) throw std::logic_error("hexant: name stack underflow");
    std::string n = std::move(names_.back());
    names_.pop_back();
    return n;
}

void Interpreter::apply_transform(runtime::TransformStep step, const p::position& where) {
    if (blocks.empty()) fail(where, "a transformation does not belong here");
    Block& b = blocks.back();
    if (auto* object = std::get_if<runtime::ObjectRecord>(&b)) {
        // As in POV-Ray, an object's texture moves with it.
        if (object->texture) object->texture->transform_by(step);
        object->transform.append(std::move(step));
    } else if (auto* light = std::get_if<runtime::LightRecord>(&b)) {
        light->transform.append(std::move(step));
    } else if (auto* camera = std::get_if<runtime::CameraRecord>(&b)) {
        runtime::CameraItem item;
        item.kind = runtime::CameraItem::Kind::Transform;
        item.step = std::move(step);
        camera->items.push_back(std::move(item));
    } else if (auto* texture = std::get_if<runtime::Texture>(&b)) {
        texture->transform_by(step);
    } else if (auto* pigment = std::get_if<runtime::Pigment>(&b)) {
        // (A declared uv-mapped pigment takes no transform from outside
        // its own block, as in POV-Ray: runtime/texture/material.hpp, UvMapping.)
        if (pigment->uv_mapping != runtime::UvMapping::Closed) pigment->transform.append(std::move(step));
    } else if (auto* normal = std::get_if<runtime::Normal>(&b)) {
        if (normal->uv_mapping != runtime::UvMapping::Closed) normal->transform.append(std::move(step));
    } else if (auto* fog = std::get_if<runtime::Fog>(&b)) {
        // (POV-Ray turns a fog's up vector; a translation does not move it.)
        if (step.kind == runtime::TransformKind::Translate) return;
        fog->up_transform.append(std::move(step));
    } else if (auto* sky = std::get_if<runtime::SkySphere>(&b)) {
        sky->transform.append(std::move(step));
    } else if (auto* transform = std::get_if<runtime::Transform>(&b)) {
        transform->append(std::move(step));
    } else if (auto* material = std::get_if<MaterialBuilder>(&b)) {
        if (material->texture) material->texture->transform_by(step);
    } else {
        fail(where, "a transformation does not belong here");
    }
}

void Interpreter::apply_deformation(runtime::TransformStep step, const p::position& where) {
    if (blocks.empty() || !std::holds_alternative<runtime::ObjectRecord>(blocks.back()))
        fail(where, "a deformation belongs in an object");
    apply_transform(std::move(step), where);
}

// ------------------------------------------------------------------ symbols

const Value* Interpreter::lookup(const std::string& name) const {
    for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it) {
        auto found = it->find(name);
        if (found != it->end()) return &found->second.value;
    }
    return nullptr;
}

const runtime::Lifetime* Interpreter::declared_when(const std::string& name) const {
    for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it) {
        auto found = it->find(name);
        if (found != it->end()) return &found->second.defined;
    }
    return nullptr;
}

void Interpreter::check_declared(const std::string& name) const {
    const runtime::Lifetime* when = declared_when(name);
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

void Interpreter::log_change(const Scope& scope, const std::string& name) {
    if (branch_logs_.empty() || restoring_) return;
    BranchLog& log = branch_logs_.back();
    const std::size_t index = static_cast<std::size_t>(&scope - scopes_.data());
    if (index >= log.scopes) return;  // a scope of this side's own (a macro's)
    VariableKey key{index, name};
    if (log.before.count(key)) return;
    log.before.emplace(key, variable_at(key));
}

std::optional<Interpreter::Held> Interpreter::variable_at(const VariableKey& key) const {
    if (key.first >= scopes_.size()) return std::nullopt;
    const Scope& scope = scopes_[key.first];
    const auto found = scope.find(key.second);
    if (found == scope.end()) return std::nullopt;
    return Held{found->second.value, found->second.defined};
}

void Interpreter::set_variable_at(const VariableKey& key, const std::optional<Held>& held) {
    Scope& scope = scopes_[key.first];
    if (held) {
        set_variable(scope, key.second, held->value);
        scope[key.second].defined = held->defined;
    } else {
        log_change(scope, key.second);
        scope.erase(key.second);
    }
}

namespace {

// What block() does not count (Interpreter::watched_edits_): the kind of
// shape and the transform (apply_transform edits the block directly). A
// side of a time split may change neither (not yet piecewise in time).
bool same_but_members(const runtime::ObjectRecord& a, const runtime::ObjectRecord& b) {
    const auto* ca = std::get_if<runtime::Csg>(&a.shape);
    const auto* cb = std::get_if<runtime::Csg>(&b.shape);
    if (a.shape.index() != b.shape.index() || (ca && ca->kind != cb->kind)) return false;
    return a.transform.steps().size() == b.transform.steps().size() &&
           a.texture.has_value() == b.texture.has_value() &&
           a.interior.has_value() == b.interior.has_value() && a.no_shadow == b.no_shadow &&
           a.hollow == b.hollow && a.inverse == b.inverse;
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
                for (const auto& piece : camera.pieces) fresh.push_back({piece.when.intersect(s->when), piece.items});
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
                colour[side] = sides[side] && sides[side]->background ? *sides[side]->background : background_before;
            if (!sides[1]) scene.background = colour[0];
            else if (!sides[0]) scene.background = colour[1];
            else
                for (int i = 0; i < 5; ++i)
                    scene.background.c[i] =
                        TimeFunction::apply(runtime::TimeOp::Conditional, c, colour[0].c[i], colour[1].c[i]);
            ++background_sets;
        }
        // The variables either side changed.
        std::map<VariableKey, bool> changed;
        for (const auto& s : sides)
            if (s)
                for (const auto& entry : s->after) changed[entry.first] = true;
        for (const auto& [key, unused] : changed) {
            (void)unused;
            const std::optional<Held> before = variable_at(key);
            std::optional<Held> values[2];
            for (int side = 0; side < 2; ++side) {
                if (!sides[side]) continue;
                const auto found = sides[side]->after.find(key);
                values[side] = found != sides[side]->after.end() ? found->second : before;
            }
            std::optional<Held> merged;
            if (!sides[1]) merged = values[0];
            else if (!sides[0]) merged = values[1];
            else if (values[0] || values[1]) {
                // Declared where either side has it, on that side's pieces.
                std::vector<runtime::Interval> declared;
                std::optional<Value> value[2];
                for (int side = 0; side < 2; ++side) {
                    if (!values[side]) continue;
                    value[side] = values[side]->value;
                    for (const auto& piece :
                         values[side]->defined.intersect(sides[side]->when).within(animation_time()))
                        declared.push_back(piece);
                }
                runtime::Lifetime defined = runtime::Lifetime::of(std::move(declared));
                if (defined.holds_all(animation_time())) defined = runtime::Lifetime::always();
                merged = Held{*merge_sides("'" + key.second + "'", c, value[0], sides[0]->when, value[1], sides[1]->when),
                              std::move(defined)};
            }
            set_variable_at(key, merged);
        }
        // The values they left (a macro's result): one each, side by side.
        if (sides[0] && sides[1] && sides[0]->pushed.size() != sides[1]->pushed.size())
            throw ValueError("the two sides of this clock-dependent branch give " +
                             std::to_string(sides[0]->pushed.size()) + " and " +
                             std::to_string(sides[1]->pushed.size()) +
                             " values; each side must give as many");
        const std::size_t count = sides[0] ? sides[0]->pushed.size() : sides[1] ? sides[1]->pushed.size() : 0;
        for (std::size_t i = 0; i < count; ++i) {
            if (!sides[1]) push(sides[0]->pushed[i]);
            else if (!sides[0]) push(sides[1]->pushed[i]);
            else
                push(*merge_sides("the value this branch gives", c, sides[0]->pushed[i], sides[0]->when,
                                  sides[1]->pushed[i], sides[1]->when));
        }
        // The object around the branch: the CSG members and lights each side
        // added (each living on its side's pieces, finish_object), and
        // nothing else changed.
        if (top_before) {
            runtime::ObjectRecord merged = *top_before;
            auto* members = std::get_if<runtime::Csg>(&merged.shape);
            const std::size_t base_members =
                members ? std::get<runtime::Csg>(top_before->shape).children.size() : 0;
            for (const auto& s : sides) {
                if (!s || !s->top) continue;
                if (s->top_edited || !same_but_members(*s->top, *top_before))
                    throw ValueError("this clock-dependent branch changes the object around it "
                                     "(a transform, texture or flag); hexant makes the CSG "
                                     "members it adds piecewise in time, not yet the object's "
                                     "own modifiers (put the branch in the value they use)");
                if (const auto* csg = std::get_if<runtime::Csg>(&s->top->shape))
                    members->children.insert(members->children.end(),
                                             csg->children.begin() + static_cast<std::ptrdiff_t>(base_members),
                                             csg->children.end());
                merged.lights.insert(merged.lights.end(),
                                     s->top->lights.begin() +
                                         static_cast<std::ptrdiff_t>(top_before->lights.size()),
                                     s->top->lights.end());
            }
            blocks.back() = std::move(merged);
        }
    } catch (const ValueError& e) {
        fail(at, e.what());
    }
}

runtime::TruthPieces Interpreter::split_domain(const TimeFunction& c, const p::position& at) {
    runtime::TruthPieces pieces;
    try {
        pieces = runtime::split_by_truth(c, domain.within(animation_time()), options.limits.time_pieces);
    } catch (const runtime::LimitError& e) {
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
    fail(where, std::string(what) +
                    " is set under a branch whose condition depends on clock; hexant makes "
                    "objects, lights, floats and vectors piecewise in time, not yet this");
}

void Interpreter::set_variable(Scope& scope, const std::string& name, Value value) {
    log_change(scope, name);
    const std::size_t bytes = string_bytes(value);
    auto [slot, added] = scope.try_emplace(name);
    Variable& variable = slot->second;
    variable.charge.attach(array_memory_);
    try {
        variable.charge.set(bytes);
    } catch (const ValueError&) {
        if (added) scope.erase(slot);  // past the budget: no variable made
        throw;
    }
    variable.value = std::move(value);
    variable.defined = runtime::Lifetime::always();  // declared now
}

void Interpreter::declare(const std::string& name, Value value, bool local) {
    // #declare of a name local to the current macro or file changes that
    // local (a macro's parameter, say); otherwise it is global.
    if (!local && scopes_.size() > 1 && scopes_.back().count(name)) local = true;
    auto& table = local ? scopes_.back() : scopes_.front();
    set_variable(table, name, std::move(value));
}

void Interpreter::assign_element(const std::string& name, const std::vector<Value>& indices,
                                 Value value, const p::position& where) {
    Value* target = nullptr;
    for (auto it = scopes_.rbegin(); it != scopes_.rend() && !target; ++it) {
        auto found = it->find(name);
        if (found != it->end()) target = &found->second.value;
    }
    if (!target) fail(where, "undeclared array '" + name + "'");
    // (An array is shared, not copied, by the sides of a time split: an
    // element set on one side would be seen on the other.)
    if (!branch_logs_.empty())
        fail(where, "an array element set under a branch whose condition depends on clock; "
                    "hexant cannot yet make an array piecewise in time (declare a float or "
                    "vector under the branch instead)");
    if (!target->is<std::shared_ptr<Array>>()) fail(where, "'" + name + "' is not an array");
    auto& array = *target->as<std::shared_ptr<Array>>();
    std::vector<double> at;
    try {
        for (const auto& i : indices) at.push_back(to_constant(i, "an array index"));
        auto& slot = array.elements[element_index(array, at)];
        array.charge.add(element_bytes(value));
        if (slot) array.charge.remove(element_bytes(**slot));
        slot = std::make_shared<Value>(std::move(value));
    } catch (const ValueError& e) {
        fail(where, e.what());
    }
}

bool Interpreter::undefine(const std::string& name) {
    for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it)
        if (it->count(name)) {
            log_change(*it, name);
            it->erase(name);
            return true;
        }
    return false;
}

namespace {

// POV-Ray's own include folder (Debian's povray-includes), readable too.
const char* const kPovRayIncludeDir = "/usr/share/povray-3.7/include";
// Debian's fonts-povray: POV-Ray's fonts (timrom.ttf, cyrvetic.ttf, ...),
// which its include folder links to.
const char* const kPovRayFontDir = "/usr/share/fonts/truetype/povray";

// Is `file` inside `folder` (both canonical)?
bool inside(const std::filesystem::path& file, const std::filesystem::path& folder) {
    auto f = file.begin();
    for (auto d = folder.begin(); d != folder.end(); ++d, ++f) {
        if (d->empty()) continue;  // a trailing separator
        if (f == file.end() || *f != *d) return false;
    }
    return true;
}

}  // namespace

namespace {

// The text of a scene or include file, checked before it is read: a
// regular file (`hexant check /dev/zero` read until memory ran out), of at
// most max_bytes (what is left of Limits::text_read). Throws ValueError
// saying what is wrong with it.
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
                         std::to_string(max_bytes) + " bytes left (--max-text-read N raises the limit)");
    std::ifstream stream(path, std::ios::binary);
    if (!stream) throw ValueError("cannot read it");
    std::string text(size, '\0');
    stream.read(text.data(), static_cast<std::streamsize>(size));
    // A file that shrank while read keeps what was there; one that grew is
    // read up to the size checked.
    text.resize(static_cast<std::size_t>(stream.gcount()));
    return text;
}

}  // namespace

std::string Interpreter::read_include(const std::filesystem::path& path, const p::position& where) {
    std::string text;
    try {
        text = read_source_text(path, options.limits.text_read - std::min(text_read_, options.limits.text_read));
    } catch (const ValueError& e) {
        fail(where, "include file '" + path.string() + "': " + e.what());
    }
    count_text(text.size(), where);
    return text;
}

std::filesystem::path Interpreter::resolve_include(const std::string& name, const p::position& where,
                                                   const std::string& what,
                                                   const std::vector<std::filesystem::path>& also) const {
    namespace fs = std::filesystem;
    const fs::path file(name);
    std::vector<fs::path> folders{scene_folder_};
    folders.insert(folders.end(), options.include_paths.begin(), options.include_paths.end());
    folders.push_back(bundled_include_dir());
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
        if (file.is_absolute()) fail(where, what + " '" + name + "' not found");
        std::string searched;
        for (const auto& folder : folders)
            searched += (searched.empty() ? "" : ", ") + folder.string();
        fail(where, what + " '" + name + "' not found (searched " + searched + ")");
    }
    // Confinement, on the file as it really is (`..` and symbolic links
    // resolved): a regular file inside a folder a scene may read. The
    // messages never show the file's contents.
    const fs::path real = fs::canonical(found, error);
    if (error) fail(where, what + " '" + name + "' cannot be read: " + error.message());
    if (!fs::is_regular_file(real, error))
        fail(where, what + " '" + name +
                        "' is not a regular file (a device, FIFO or folder "
                        "cannot be read)");
    std::vector<fs::path> allowed = folders;
    allowed.push_back(kPovRayIncludeDir);
    allowed.insert(allowed.end(), options.read_paths.begin(), options.read_paths.end());
    for (const fs::path system : {"/proc", "/sys", "/dev"})
        if (inside(real, system))
            fail(where, what + " '" + name + "' is a system file: refused");
    for (const auto& folder : allowed) {
        const fs::path root = fs::weakly_canonical(folder.empty() ? fs::path(".") : folder, error);
        if (!error && inside(real, root)) return real;
    }
    fail(where, what + " '" + name +
                    "' is outside the folders a scene may read (its own "
                    "folder, the -L folders and the include folders; --allow-read DIR adds one)");
}

// ------------------------------------------------------------------ objects

namespace {

// The walks below over an object and the objects nested in it keep their
// own stack, not the thread's: a record may nest kMaxObjectDepth deep, and
// a frame per level overflowed the main thread's 8 MB under AddressSanitizer
// (whose frames are several times larger).

// Calls visit(record) for the object and every object nested in it.
template <class Visit>
void for_each_nested(const runtime::ObjectRecord& object, Visit visit) {
    std::vector<const runtime::ObjectRecord*> pending{&object};
    while (!pending.empty()) {
        const runtime::ObjectRecord* record = pending.back();
        pending.pop_back();
        visit(*record);
        if (const auto* csg = std::get_if<runtime::Csg>(&record->shape))
            for (auto it = csg->children.rbegin(); it != csg->children.rend(); ++it)
                pending.push_back(it->get());  // reversed: children visited in order
    }
}

}  // namespace

// A pattern hexant lacks, in a pigment (its pigment map's too) or a
// normal: the error where the scene uses it (check says it, not only render).
namespace {

// (A declared graph of maps may share entries: each is checked once. A
// texture and its pigment share an address: the kind is part of the key.)
using Checked = std::set<std::pair<int, const void*>>;
void check(const runtime::Pigment& pigment, Checked& seen) {
    if (!seen.insert({0, &pigment}).second) return;
    if (pigment.pattern == runtime::Pigment::Pattern::Unsupported)
        throw ValueError("pigment pattern '" + pigment.unsupported_name + "' (written at " +
                         pigment.unsupported_place.to_string() + ") is not supported by hexant");
    for (const auto& entry : pigment.pigment_map) check(*entry.pigment, seen);
}
void check(const runtime::Normal& normal, Checked& seen) {
    if (!seen.insert({1, &normal}).second) return;
    if (!normal.unsupported_name.empty())
        throw ValueError("normal pattern '" + normal.unsupported_name + "' (written at " +
                         normal.unsupported_place.to_string() + ") is not supported by hexant");
    for (const auto& entry : normal.normal_map) check(*entry.normal, seen);
}
void check(const runtime::Texture& texture, Checked& seen) {
    if (!seen.insert({2, &texture}).second) return;
    check(texture.pigment, seen);
    if (texture.normal) check(*texture.normal, seen);
    for (const auto& layer : texture.below) check(layer, seen);
    for (const auto& entry : texture.texture_map) check(*entry.texture, seen);
}

}  // namespace

void check_pigment(const runtime::Pigment& pigment) {
    Checked seen;
    check(pigment, seen);
}
void check_normal(const std::optional<runtime::Normal>& normal) {
    Checked seen;
    if (normal) check(*normal, seen);
}
void check_texture(const runtime::Texture& texture) {
    Checked seen;
    check(texture, seen);
}

namespace {

void check_patterns(const runtime::ObjectRecord& object) {
    for_each_nested(object, [](const runtime::ObjectRecord& record) {
        if (record.texture) check_texture(*record.texture);
    });
}

// Lights inside CSGs move with them: hand them to the scene with the
// transforms of every object around them.
void collect_lights(const runtime::ObjectRecord& object, std::vector<runtime::LightRecord>& lights) {
    struct Pending {
        const runtime::ObjectRecord* record;
        // The transform of the objects around it, shared by its siblings: a
        // union of 10^5 objects holds one copy, not one per child.
        std::shared_ptr<const runtime::Transform> outer;
    };
    std::vector<Pending> pending{{&object, std::make_shared<const runtime::Transform>()}};
    while (!pending.empty()) {
        const Pending p = std::move(pending.back());
        pending.pop_back();
        auto here = std::make_shared<runtime::Transform>(p.record->transform);
        here->append(*p.outer);
        for (auto light : p.record->lights) {
            light.transform.append(*here);
            lights.push_back(std::move(light));
        }
        if (const auto* csg = std::get_if<runtime::Csg>(&p.record->shape))
            for (auto it = csg->children.rbegin(); it != csg->children.rend(); ++it)
                pending.push_back({it->get(), here});
    }
}

}  // namespace

void Interpreter::check_parameters(const runtime::ObjectRecord& object,
                                   const p::position& where) const {
    for_each_nested(object, [&](const runtime::ObjectRecord& record) {
        std::optional<std::string> problem = runtime::bad_parameter(record, scene.animation);
        for (std::size_t i = 0; !problem && i < record.lights.size(); ++i)
            problem = runtime::bad_parameter(record.lights[i], scene.animation);
        if (!problem) return;
        if (record.place.file.empty()) fail(where, *problem);
        SceneError error(*problem, place(record.place));
        if (record.place.file != where.source || record.place.line != where.line)
            error.add_context(place(where, "in the object added to the scene here"));
        throw error;
    });
}

void Interpreter::add_object(const runtime::ObjectPtr& object, const p::position& where) {
    try {
        check_patterns(*object);
    } catch (const ValueError& e) {
        fail(where, e.what());
    }
    check_parameters(*object, where);
    std::vector<runtime::LightRecord> lights;
    collect_lights(*object, lights);
    scene.objects.push_back(object);
    for (auto& light : lights) add_light(std::move(light), where);
}

void Interpreter::add_light(runtime::LightRecord light, const p::position& where) {
    if (light.looks_like) {
        // POV-Ray's Parse_Light_Source: the object moved to the light's
        // centre and through its own modifiers (as it was read), no_shadow,
        // then transformed with the light. (POV-Ray moves it to the centre
        // as the transforms written before looks_like left it, without
        // turning it by them; hexant turns it by every transform of the
        // light.)
        runtime::ObjectRecord placed = *light.looks_like;
        placed.transform.append(light.transform);
        placed.no_shadow = true;
        placed.lifetime = placed.lifetime.intersect(light.lifetime);
        light.looks_like.reset();
        add_object(std::make_shared<const runtime::ObjectRecord>(std::move(placed)), where);
    }
    scene.lights.push_back(std::move(light));
}

void fill_array(Array& array, const Array& list, std::size_t dimension, std::size_t& next) {
    const int want = array.dimensions[dimension];
    if (static_cast<int>(list.elements.size()) != want)
        throw ValueError("the array's dimension " + std::to_string(dimension + 1) + " has " +
                         std::to_string(want) + " elements but " +
                         std::to_string(list.elements.size()) + " were given");
    for (const auto& element : list.elements) {
        const Value& v = **element;
        const bool is_list = v.is<std::shared_ptr<Array>>() &&
                             v.as<std::shared_ptr<Array>>()->dimensions.empty();
        if (dimension + 1 < array.dimensions.size()) {
            if (!is_list) throw ValueError("expected a { } list for the array's next dimension");
            fill_array(array, *v.as<std::shared_ptr<Array>>(), dimension + 1, next);
        } else {
            if (is_list) throw ValueError("the array has fewer dimensions than this { } list");
            array.charge.add(element_bytes(v));
            array.elements[next++] = std::make_shared<Value>(v);
        }
    }
}

namespace {

// A shape block's values for its kind's read (runtime/objects/shape_arguments.hpp),
// converted by the language's own rules; errors are ValueErrors, which the
// rule reading the block places.
class BlockArguments final : public runtime::objects::ShapeArguments {
  public:
    BlockArguments(std::string keyword, std::vector<std::string> options, std::vector<Value>& values,
                   const Interpreter& st, const p::position& where)
        : keyword_(std::move(keyword)), options_(std::move(options)), values_(values), st_(st),
          where_(where) {}

    const std::string& keyword() const override { return keyword_; }
    const std::vector<std::string>& options() const override { return options_; }
    std::size_t size() const override { return values_.size(); }
    TimeFunction number(std::size_t i, const std::string& what) const override {
        return to_float(at(i), what);
    }
    runtime::Vector3Function vector3(std::size_t i, const std::string& what) const override {
        return to_vector3(at(i), what);
    }
    runtime::Vector2Function vector2(std::size_t i, const std::string& what) const override {
        return to_vector2(at(i), what);
    }
    double constant(std::size_t i, const std::string& what) const override {
        return to_constant(at(i), what);
    }
    std::string string(std::size_t i, const std::string& what) const override {
        return to_string_value(at(i), what);
    }
    std::filesystem::path find_file(const std::string& name, const std::string& kind) const override {
        if (name.empty()) fail(keyword_ + "'s " + kind + " name is empty");
        // Also where POV-Ray's default library path finds them on Debian;
        // the system's fonts may be named by their path.
        return st_.resolve_include(name, where_, kind,
                                   {kPovRayIncludeDir, kPovRayFontDir, "/usr/share/fonts"});
    }
    const std::string& charset() const override { return st_.charset; }
    [[noreturn]] void fail(const std::string& message) const override { throw ValueError(message); }

  private:
    const Value& at(std::size_t i) const {
        if (i >= values_.size()) fail(keyword_ + " has no value " + std::to_string(i + 1));
        return values_[i];
    }

    std::string keyword_;
    std::vector<std::string> options_;
    std::vector<Value>& values_;
    const Interpreter& st_;
    p::position where_;
};

template <class... Kinds>
void read_shape(const std::string& keyword, const runtime::objects::ShapeArguments& args,
                runtime::ObjectRecord& record, runtime::objects::KindList<Kinds...>) {
    // (Kinds with a rule of their own are never read here.)
    const bool found = ((keyword == Kinds::keyword ? ([&] {
        if constexpr (!runtime::objects::kind_detail::own_syntax<Kinds>()) {
            record.shape = Kinds::read(args);
            // What POV-Ray applies before the scene's own transformations.
            if constexpr (requires { Kinds::placement(); }) record.transform = Kinds::placement();
        }
    }(), true) : false) || ...);
    if (!found) throw std::logic_error("hexant: unknown shape " + keyword);
}

// The most objects one shape may become by strings that change with clock
// (str(clock) over 10,000 frames is 10,000 texts).
constexpr std::size_t kMaxTimedStringObjects = 100'000;

}  // namespace

runtime::ObjectRecord make_shape(const std::string& kind, std::vector<std::string> options,
                                 std::vector<Value>& args, Interpreter& st, const p::position& where) {
    // A string value that changes with clock (str(clock, 0, 2), a branch on
    // clock naming two fonts): one object per text, each living while its
    // text holds, together in a union. (Further such strings split each.)
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (!args[i].is<TimedString>()) continue;
        const auto texts = args[i].as<TimedString>().by_text();
        if (texts.size() > kMaxTimedStringObjects)
            throw ValueError(kind + "'s value " + std::to_string(i + 1) + " changes with clock into " +
                             std::to_string(texts.size()) + " different strings, more than " +
                             std::to_string(kMaxTimedStringObjects) + " objects");
        runtime::Csg group;
        for (const auto& [text, life] : texts) {
            std::vector<Value> one = args;
            one[i] = Value{text};
            runtime::ObjectRecord child = make_shape(kind, options, one, st, where);
            child.lifetime = child.lifetime.intersect(life);
            child.place = st.shape_place;
            group.children.push_back(std::make_shared<const runtime::ObjectRecord>(std::move(child)));
        }
        runtime::ObjectRecord record;
        record.shape = std::move(group);
        return record;
    }
    const BlockArguments arguments(kind, std::move(options), args, st, where);
    runtime::ObjectRecord record;
    read_shape(kind, arguments, record, runtime::ShapeKinds{});
    return record;
}

void set_shape_setting(runtime::ObjectRecord& record, const std::string& name,
                       std::vector<Value>& values, Interpreter& st, const p::position& where) {
    const BlockArguments value(name, {}, values, st, where);
    bool taken = false;
    std::visit(
        [&](auto& shape) {
            using Kind = std::decay_t<decltype(shape)>;
            if constexpr (requires { shape.set(name, value); })
                if (runtime::objects::takes_setting<Kind>(name)) {
                    shape.set(name, value);
                    taken = true;
                }
        },
        record.shape);
    if (taken) return;
    // Which kinds it belongs to, for the message.
    std::vector<std::string> owners;
    [&]<class... Kinds>(runtime::objects::KindList<Kinds...>) {
        ((runtime::objects::takes_setting<Kinds>(name) ? (owners.emplace_back(Kinds::keyword), 0) : 0),
         ...);
    }(runtime::ShapeKinds{});
    std::string kinds;
    for (std::size_t i = 0; i < owners.size(); ++i)
        kinds += (i == 0 ? "" : i + 1 == owners.size() ? " or " : ", ") + owners[i];
    throw ValueError("'" + name + "' belongs to a " + kinds + ", not a " +
                     runtime::shape_name(record.shape));
}

void add_blob_component(runtime::ObjectRecord& record, const std::string& kind,
                        std::vector<Value>& values, Interpreter& st, const p::position& where) {
    auto* blob = std::get_if<runtime::Blob>(&record.shape);
    if (!blob) throw ValueError("a blob component belongs in a blob");
    const BlockArguments args("blob " + kind, {}, values, st, where);
    blob->add_component(kind, args);
}

// ------------------------------------------------------------------ entry points

namespace {

// A Declare= value is a value, never scene text (a ';' or '#' would splice
// directives into the scene): a number, a vector of numbers or a string
// without quotes inside. POV-Ray 3.7 itself takes a float only.
void check_declare(const std::string& key, const std::string& value) {
    static const std::regex name("[A-Za-z_][A-Za-z0-9_]*");
    static const std::string number = R"([+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?)";
    static const std::regex accepted("\\s*(" + number + "|<\\s*" + number + "(\\s*,\\s*" + number +
                                     ")*\\s*>|\"[^\"\\\\\\n]*\")\\s*");
    if (!std::regex_match(key, name))
        throw SceneError("the name must be an identifier", ErrorPlace{"--declare " + key, 0, 0, "", ""});
    if (!std::regex_match(value, accepted))
        throw SceneError("the value '" + value +
                             "' must be a number, a vector of numbers <a, b, c> or a \"string\" "
                             "(it is never read as scene text)",
                         ErrorPlace{"--declare " + key, 0, 0, "", ""});
    // A number past the doubles (1e999) reads as an infinity.
    if (value.find('"') == std::string::npos) {
        static const std::regex each(number);
        for (auto it = std::sregex_iterator(value.begin(), value.end(), each);
             it != std::sregex_iterator(); ++it)
            if (!std::isfinite(std::strtod(it->str().c_str(), nullptr)))
                throw SceneError("the number " + it->str() + " is beyond the doubles (infinite)",
                                 ErrorPlace{"--declare " + key, 0, 0, "", ""});
    }
}

runtime::SceneDescription parse(const std::string& text, const std::string& name,
                                const std::filesystem::path& folder, const ParseOptions& options) {
    const NestingGuard nesting;  // the reader's stack is measured from here
    runtime::SceneDescription scene;
    scene.animation = options.animation;
    Interpreter interpreter(options, scene, folder);
    // Declare= / --declare: each value is read as an expression.
    for (const auto& [key, value] : options.declares) {
        check_declare(key, value);
        const std::string source = "#declare " + key + " = " + value + ";";
        interpreter.read_file<grammar::scene_item, action, control>("--declare " + key, source);
    }
    interpreter.read_file<grammar::scene_item, action, control>(name, text);
    return scene;
}

}  // namespace

runtime::SceneDescription parse_scene_file(const std::filesystem::path& path,
                                           const ParseOptions& options) {
    std::string text;
    try {
        text = read_source_text(path, options.limits.text_read);
    } catch (const ValueError& e) {
        throw SceneError(std::string("cannot read the scene file: ") + e.what(),
                         ErrorPlace{path.string(), 0, 0, {}, {}});
    }
    const auto folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    return parse(text, path.string(), folder, options);
}

runtime::SceneDescription parse_scene_text(const std::string& text, const std::string& name,
                                           const ParseOptions& options) {
    return parse(text, name, std::filesystem::current_path(), options);
}

}  // namespace hexant::language
