// #fopen, #fclose, #write and #read (language/file_io.hpp). The open
// file's name stays on the name stack while a #write or #read is read.
// Part of the actions (language/actions.hpp).
#pragma once

#include "language/actions/height_field_function.hpp"
#include "language/actions/polys.hpp"
#include "language/file_io.hpp"

namespace hexant::language {

// ------------------------------------------------------------ files

// A file is opened, written or read only where it happens at every
// instant: under a branch on clock it would happen on some frames only,
// and hexant reads the scene once for them all.
inline void check_file_domain(const Interpreter& st, const char* what) {
    if (!st.domain.is_always())
        throw ValueError(std::string(what) +
                         " under a branch whose condition depends on clock: hexant reads a "
                         "scene once for the whole animation (render the frames one by one "
                         "with --clock to give each its own files)");
}

template <>
struct action<g::fopen_id> : name_action {};
template <>
struct action<g::fopen_mode> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        const std::string mode = word(in);
        const Value file = st.values.pop();
        const std::string id = st.values.pop_name();
        check_file_domain(st, "#fopen");
        if (!file.is<std::string>())
            throw ValueError("#fopen needs the file's name as a string, not a " + type_name(file));
        const std::string& name = file.as<std::string>();
        if (st.user_files.is_open(id))
            throw ValueError("'" + id + "' is open already (#fclose it first)");
        std::vector<std::filesystem::path> writable = st.options.write_paths;
        if (!st.options.output_folder.empty())
            writable.insert(writable.begin(), st.options.output_folder);
        if (mode == "read") {
            const auto path = st.resolve_include(name, in.position(), "file", writable);
            st.user_files.open_read(id, path, st.read_include(path, in.position()));
        } else {
            if (st.options.output_folder.empty() && st.options.write_paths.empty())
                throw ValueError("#fopen '" + name +
                                 "' for writing: this reading has no output folder (a scene "
                                 "writes into its render's output folder, or where "
                                 "--allow-write DIR says)");
            std::filesystem::path path;
            try {
                path = writable_path(name, st.options.output_folder, st.options.write_paths);
            } catch (const ValueError& e) {
                throw ValueError("#fopen '" + name + "' for writing: " + e.what());
            }
            try {
                st.user_files.open_write(id, path, mode == "append");
            } catch (const ValueError& e) {
                throw ValueError("#fopen '" + name + "' for writing: " + e.what());
            }
        }
        // The name is defined while the file is open (#read's loops test it).
        st.symbols.declare(id, Value{std::string(name)}, false);
    }
};
template <>
struct action<g::fclose_id> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        const std::string id = word(in);
        // POV-Ray closes a file #read to its end by itself; closing it
        // again is no error there either.
        if (!st.user_files.is_open(id)) return;
        st.symbols.undefine(id);  // (first: closed, the file is gone even if its flush fails)
        st.user_files.close(id);
    }
};
template <>
struct action<g::file_id> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        const std::string id = word(in);
        if (!st.user_files.is_open(id))
            throw ValueError("'" + id + "' is not an open file (#fopen it first)");
        st.values.push_name(id);
        st.file_read_ended = false;
    }
};
template <>
struct action<g::file_close> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, Interpreter& st) {
        (void)st.values.pop_name();
    }
};
// The open file's name, left on the name stack.
inline std::string open_file_name(Interpreter& st) {
    std::string id = st.values.pop_name();
    st.values.push_name(id);
    return id;
}
template <>
struct action<g::write_value> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, Interpreter& st) {
        const Value v = st.values.pop();
        check_file_domain(st, "#write");
        st.user_files.write(open_file_name(st), written_text(v));
    }
};
template <>
struct action<g::write_binary_word> : name_action {};
template <>
struct action<g::write_binary_value> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, Interpreter& st) {
        const Value v = st.values.pop();
        const std::string binary = st.values.pop_name();
        check_file_domain(st, "#write");
        st.user_files.write(open_file_name(st), written_bytes(binary, v));
    }
};
// Each identifier takes the file's next item; at the file's end POV-Ray
// closes it and undefines its name, and leaves the rest unset.
template <>
struct action<g::read_target> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        if (st.file_read_ended) return;
        check_file_domain(st, "#read");
        const std::string id = open_file_name(st);
        std::optional<Value> item = st.user_files.read(id);
        if (!item) {
            st.user_files.close(id);
            st.symbols.undefine(id);
            st.file_read_ended = true;
            return;
        }
        st.symbols.declare(word(in), std::move(*item), false);
    }
};

}  // namespace hexant::language
