// Every limit that stops a runaway or hostile scene, in one place, with its
// default. A scene that passes one gets an error at the place it did so
// (file:line:col, exit 1); the command line raises each (README, "Limits").
// POV-Ray itself has few of these: a runaway #while there runs until it is
// killed, and an array or string grows until the allocation fails.
#pragma once

#include <cstddef>
#include <cstdint>

namespace hexant::language {

struct Limits {
    // Iterations of one #while or #for.
    std::size_t loop_iterations = 10'000'000;
    // Loop iterations and macro calls of the whole reading together (nested
    // loops multiply: two nested loops of 10^5 each stay under the per-loop
    // limit but take 10^10 steps). A turn of `#declare S = S + 1;` takes
    // 2.1 us and a macro call 2-4 us (2026-12-06): 10^7 of them about half
    // a minute; the former 10^8 let a doubly recursive macro (Fibonacci of
    // 40) run for six minutes before it stopped (issue 45).
    std::size_t total_iterations = 10'000'000;
    // Bytes of scene text the reader goes over: every file once per
    // #include, a loop's body once per turn and a macro's body once per
    // call. Iterations alone do not bound the work: a loop whose 50 KB body
    // is stepped over (a #switch matching no case) takes 1.7 ms a turn, so
    // 10^7 turns would take four hours (found by the fuzzer). That body is
    // 1 GiB in 10 s (111 MB/s stepped over), and 1 GiB leaves room for 10^6
    // turns of a 1 KB body.
    std::size_t text_read = std::size_t(1) << 30;
    // Macro calls inside macro calls, and #include inside #include.
    int macro_depth = 200;
    int include_depth = 100;
    // Characters of one string (concat() doubling a string reached the
    // allocator's limit in 30 steps).
    std::size_t string_length = 16u << 20;
    // Bytes held by the scene's arrays at once: their slots, the values set
    // in them and those values' strings (an array at the former 10^8 element
    // limit took 4.8 GB), and the strings its variables hold (a thousand
    // names of 16 Mi characters each would take 16 GB). Counted per copy:
    // an array is a value in SDL.
    std::size_t array_memory = std::size_t(2) << 30;
    // Frames of an animation (10^6 is eleven hours of film at 24 per
    // second); frames are counted in int and each frame's eye and lights
    // are placed up front.
    long long frames = 1'000'000;
    // Pixels of one image (width times height): an image keeps 12 bytes a
    // pixel in float RGB, and the file's writer and a kept frame copies it
    // (-W 100000 -H 100000 ended in std::bad_alloc).
    long long image_pixels = 100'000'000;
    // Pieces of time a clock-dependent branch splits the animation into,
    // per condition (#if (sin(1 / (clock - 0.5)) > 0) would split it
    // without end): each piece runs the branch's text again.
    std::size_t time_pieces = 10'000;
    // Bytes of #debug text printed over the whole reading (a loop printing
    // filled 6.5 GB of a log in a minute, issue 45); 64 MiB is a million
    // lines of 64 characters.
    std::size_t debug_output = std::size_t(64) << 20;
    // Objects the scene makes for the render: each shape, each member of
    // a CSG (a copy of a declared union is all its members again), each
    // clipped_by and bounded_by object. An object takes about 3.5 KB while
    // it is rendered (10^6 spheres peaked at 3.5 GB, 2026-12-06); a union
    // doubled 30 times in a loop asked for 2^30 (issue 45).
    std::uint64_t objects = 1'000'000;
    // Triangles of the scene's meshes (mesh and mesh2), counted as they
    // are read: about 340 bytes each until the mesh is built (10^6
    // triangles from a #for loop: 342 MB, 9 s); 4*10^6 stay under 1.5 GB.
    std::uint64_t triangles = 4'000'000;
};

}  // namespace hexant::language
