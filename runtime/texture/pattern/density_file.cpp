#include "runtime/texture/pattern/density_file.hpp"

#include <cmath>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace hexant::runtime::pattern {

namespace {

// POV-Ray's intp3 (pattern.cpp), in single precision as there: the cubic
// through fb at 0 and fc at 1 with slopes from fa and fd.
float intp3(float t, float fa, float fb, float fc, float fd) {
    const float b = (fc - fa) * 0.5f;
    const float d = (fd - fb) * 0.5f;
    const float e = 2.0f * (fb - fc) + b + d;
    const float f = -3.0f * (fb - fc) - 2.0f * b - d;
    return ((e * t + f) * t + b) * t + fb;
}

// POV-Ray's zmax on its unsigned index: an index one below 0 wraps as
// size_t does, then modulo the size.
std::size_t wrap(std::size_t i, std::size_t size) {
    return i % size;
}

}  // namespace

DensityFile DensityFile::read(const std::filesystem::path& path, std::uint64_t max_voxels) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read the density file " + path.string());
    // The header first: the bytes read are bounded by what it declares,
    // never by the file (a 65535^3 header, or a file of any size, issue 45).
    std::vector<unsigned char> bytes(6);
    in.read(reinterpret_cast<char*>(bytes.data()), 6);
    if (in.gcount() < 6)
        throw std::runtime_error("the density file " + path.string() +
                                 " is shorter than its 6-byte header");
    DensityFile d;
    const auto u16 = [&](std::size_t at) { return std::size_t(bytes[at]) << 8 | bytes[at + 1]; };
    d.sx = u16(0);
    d.sy = u16(2);
    d.sz = u16(4);
    const std::size_t count = d.sx * d.sy * d.sz;
    if (count > max_voxels)
        throw std::runtime_error("the density file " + path.string() + " declares " +
                                 std::to_string(d.sx) + " x " + std::to_string(d.sy) + " x " +
                                 std::to_string(d.sz) + " voxels, more than the limit of " +
                                 std::to_string(max_voxels) + " (--max-pixels N raises it)");
    std::error_code error;
    const std::uintmax_t file_bytes = std::filesystem::file_size(path, error);
    if (error) throw std::runtime_error("cannot read the density file " + path.string());
    const std::size_t length = file_bytes - 6;
    if (length == count * 4 || length == count * 2 || length == count) {
        bytes.resize(6 + length);
        in.read(reinterpret_cast<char*>(bytes.data() + 6), static_cast<std::streamsize>(length));
        if (static_cast<std::size_t>(in.gcount()) != length)
            throw std::runtime_error("the density file " + path.string() +
                                     " changed while it was read");
    }
    std::size_t size = 0;
    if (count * 4 == length)
        size = 4;
    else if (count * 2 == length)
        size = 2;
    else if (count == length)
        size = 1;
    else
        throw std::runtime_error(
            "the density file " + path.string() + " holds " + std::to_string(length) +
            " bytes of voxels, not 1, 2 or 4 for each of " + std::to_string(d.sx) + " x " +
            std::to_string(d.sy) + " x " + std::to_string(d.sz) +
            " (POV-Ray's \"Invalid density file size\")");
    d.scale_ = size == 4 ? 4294967295.0 : size == 2 ? 65535.0 : 255.0;
    d.voxels_.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        std::uint32_t v = 0;
        for (std::size_t k = 0; k < size; ++k) v = v << 8 | bytes[6 + i * size + k];
        d.voxels_[i] = v;
    }
    return d;
}

double DensityFile::value(const glm::dvec3& p, int interpolation) const {
    if (sx == 0 || sy == 0 || sz == 0) return 0.0;
    if (!(p.x >= 0.0 && p.x < 1.0 && p.y >= 0.0 && p.y < 1.0 && p.z >= 0.0 && p.z < 1.0))
        return 0.0;
    double density = 0.0;
    switch (interpolation % 10) {
        case 0: {
            const auto x = std::size_t(p.x * double(sx)), y = std::size_t(p.y * double(sy)),
                       z = std::size_t(p.z * double(sz));
            density = x < sx && y < sy && z < sz ? voxel(x, y, z) : 0.0;
            break;
        }
        case 1: {
            double xx = p.x * double(sx), yy = p.y * double(sy), zz = p.z * double(sz);
            const auto x1 = std::size_t(xx), y1 = std::size_t(yy), z1 = std::size_t(zz);
            const std::size_t x2 = (x1 + 1) % sx, y2 = (y1 + 1) % sy, z2 = (z1 + 1) % sz;
            xx -= std::floor(xx);
            yy -= std::floor(yy);
            zz -= std::floor(zz);
            const double xi = 1.0 - xx, yi = 1.0 - yy;
            density = ((voxel(x1, y1, z1) * xi + voxel(x2, y1, z1) * xx) * yi +
                       (voxel(x1, y2, z1) * xi + voxel(x2, y2, z1) * xx) * yy) *
                          (1.0 - zz) +
                      ((voxel(x1, y1, z2) * xi + voxel(x2, y1, z2) * xx) * yi +
                       (voxel(x1, y2, z2) * xi + voxel(x2, y2, z2) * xx) * yy) *
                          zz;
            break;
        }
        default: {
            double xx = p.x * double(sx), yy = p.y * double(sy), zz = p.z * double(sz);
            const auto x1 = std::size_t(xx), y1 = std::size_t(yy), z1 = std::size_t(zz);
            xx -= std::floor(xx);
            yy -= std::floor(yy);
            zz -= std::floor(zz);
            const std::size_t k[4] = {wrap(z1 - 1, sz), wrap(z1, sz), wrap(z1 + 1, sz),
                                      wrap(z1 + 2, sz)};
            float plane[4][4];
            for (std::size_t i = 0; i < 4; ++i) {
                const std::size_t ii = wrap(i + x1 - 1, sx);
                for (std::size_t j = 0; j < 4; ++j) {
                    const std::size_t jj = wrap(j + y1 - 1, sy);
                    plane[i][j] =
                        intp3(float(zz), float(voxel(ii, jj, k[0])), float(voxel(ii, jj, k[1])),
                              float(voxel(ii, jj, k[2])), float(voxel(ii, jj, k[3])));
                }
            }
            // (POV-Ray writes the row of results over plane[0], each read
            // before it is written.)
            for (std::size_t i = 0; i < 4; ++i)
                plane[0][i] = intp3(float(yy), plane[i][0], plane[i][1], plane[i][2], plane[i][3]);
            density = intp3(float(xx), plane[0][0], plane[0][1], plane[0][2], plane[0][3]);
            break;
        }
    }
    return density < 0.0 ? 0.0 : density;
}

}  // namespace hexant::runtime::pattern
