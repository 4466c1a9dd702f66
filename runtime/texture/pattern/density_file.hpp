// POV-Ray's density_file df3: a box of voxels read from a .df3 file (three
// big-endian 16-bit sizes, x y z, then the voxels, x fastest, of 1, 2 or 4
// big-endian bytes each, the size told by the file's length), whose value
// at a point of the unit cube [0, 1)^3 is the voxel there, trilinearly or
// tricubically interpolated, and 0 outside (POV-Ray 3.7's
// Read_Density_File and density_pattern, pattern.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <vector>

#include <glm/vec3.hpp>

namespace hexant::runtime::pattern {

class DensityFile {
  public:
    // Throws std::runtime_error naming the file when it is not a df3: too
    // short, or a length that no voxel size fits; or when its header
    // declares more than `max_voxels` (checked before the voxels are read:
    // the file is read only once its size is known to fit the header).
    static DensityFile read(const std::filesystem::path& path,
                            std::uint64_t max_voxels = 100'000'000);

    // The value at `point` (pattern space), 0 outside the unit cube:
    // `interpolation` 0 the voxel itself, 1 trilinear, 2 (and any other
    // POV-Ray reads modulo 10) tricubic, each wrapping at the far faces
    // as POV-Ray's does. Never below 0.
    double value(const glm::dvec3& point, int interpolation) const;

    std::size_t sx = 0, sy = 0, sz = 0;

  private:
    double voxel(std::size_t x, std::size_t y, std::size_t z) const {
        return voxels_[(z * sy + y) * sx + x] / scale_;
    }
    std::vector<std::uint32_t> voxels_;
    double scale_ = 255.0;  // the largest voxel value of its size
};

}  // namespace hexant::runtime::pattern
