// POV-Ray's density_file df3 (runtime/texture/pattern/density_file.hpp):
// the file's sizes decide the voxel size, a length no size fits is
// refused, and the value at a voxel's centre, between voxels and outside
// the unit cube is POV-Ray's.
#include "runtime/texture/pattern/density_file.hpp"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

#include <catch2/catch.hpp>

namespace fs = std::filesystem;
using hexant::runtime::pattern::DensityFile;

namespace {

// A df3 of sx x sy x sz voxels of `bytes` bytes each, big-endian, valued
// by `value(x, y, z)`; `extra` bytes appended.
template <class F>
fs::path write_df3(const char* name, int sx, int sy, int sz, int bytes, F value, int extra = 0) {
    const fs::path path = fs::temp_directory_path() / name;
    std::ofstream out(path, std::ios::binary);
    const auto put = [&](std::uint32_t v, int n) {
        for (int k = n - 1; k >= 0; --k) out.put(char((v >> (8 * k)) & 0xff));
    };
    put(std::uint32_t(sx), 2);
    put(std::uint32_t(sy), 2);
    put(std::uint32_t(sz), 2);
    for (int z = 0; z < sz; ++z)
        for (int y = 0; y < sy; ++y)
            for (int x = 0; x < sx; ++x) put(value(x, y, z), bytes);
    for (int i = 0; i < extra; ++i) out.put(0);
    return path;
}

}  // namespace

TEST_CASE("a df3 file's voxels as POV-Ray reads them", "[pattern][density_file]") {
    const auto ramp = [](int x, int y, int z) { return std::uint32_t(x + 4 * y + 16 * z); };
    SECTION("8-bit voxels, each at its cell, none outside") {
        const DensityFile d = DensityFile::read(write_df3("hexant_df3_8.df3", 4, 4, 4, 1, ramp));
        CHECK(d.sx == 4);
        // The voxel whose cell holds the point, over 255.
        CHECK(d.value({0.1, 0.1, 0.1}, 0) == Approx(0.0));
        CHECK(d.value({0.3, 0.6, 0.9}, 0) == Approx((1 + 4 * 2 + 16 * 3) / 255.0));
        CHECK(d.value({1.0, 0.5, 0.5}, 0) == 0.0);
        CHECK(d.value({-0.01, 0.5, 0.5}, 1) == 0.0);
        // Trilinear: halfway between voxels 1 and 2 along x at a cell's
        // corner in y and z.
        CHECK(d.value({1.5 / 4, 0.0, 0.0}, 1) == Approx(1.5 / 255.0));
        // Tricubic through a linear ramp inside the box: the ramp.
        CHECK(d.value({1.5 / 4, 1.0 / 4, 1.0 / 4}, 2) ==
              Approx((1.5 + 4 + 16) / 255.0).epsilon(1e-5));
    }
    SECTION("16- and 32-bit voxels over their largest values") {
        const auto big = [](int, int, int) { return std::uint32_t(65535); };
        CHECK(DensityFile::read(write_df3("hexant_df3_16.df3", 2, 2, 2, 2, big))
                  .value({0.5, 0.5, 0.5}, 0) == Approx(1.0));
        const auto half = [](int, int, int) { return std::uint32_t(2147483648u); };
        CHECK(DensityFile::read(write_df3("hexant_df3_32.df3", 2, 2, 2, 4, half))
                  .value({0.5, 0.5, 0.5}, 0) == Approx(0.5));
    }
    SECTION("a length that fits no voxel size, or no header, is refused") {
        CHECK_THROWS_AS(DensityFile::read(write_df3("hexant_df3_bad.df3", 3, 3, 3, 1, ramp, 5)),
                        std::runtime_error);
        const fs::path short_file = fs::temp_directory_path() / "hexant_df3_short.df3";
        std::ofstream(short_file, std::ios::binary) << "abc";
        CHECK_THROWS_AS(DensityFile::read(short_file), std::runtime_error);
        CHECK_THROWS_AS(DensityFile::read(fs::temp_directory_path() / "hexant_no_such.df3"),
                        std::runtime_error);
    }
    SECTION("a header past the limit is refused before the voxels are read (issue 45)") {
        // 65535^3 declared in a file of 6 bytes: refused by the header alone.
        const fs::path huge = fs::temp_directory_path() / "hexant_df3_huge.df3";
        std::ofstream(huge, std::ios::binary) << std::string(6, char(0xff));
        CHECK_THROWS_WITH(DensityFile::read(huge),
                          Catch::Contains("65535 x 65535 x 65535 voxels, more than the limit"));
        // Within the limit it reads; one voxel fewer allowed, it does not.
        const fs::path cube = write_df3("hexant_df3_limit.df3", 4, 4, 4, 1, ramp);
        CHECK_NOTHROW(DensityFile::read(cube, 64));
        CHECK_THROWS_WITH(DensityFile::read(cube, 63), Catch::Contains("--max-pixels"));
    }
}
