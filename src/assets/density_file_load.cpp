#include "assets/loaders.h"
#include "core/limits.h"

#include <filesystem>
#include <fstream>
#include <fmt/format.h>

namespace drt {

// df3: three big-endian 16-bit sizes nx, ny, nz, then nx * ny * nz voxels of 1,
// 2 or 4 bytes each (big-endian, unsigned, read as fractions of their largest
// value), x fastest, then y, then z. The voxel size is what the file's length
// leaves for each voxel. Not an image: OpenImageIO has no reader for it.
std::string loadDensityFile(DensityFile& d, const Limits& limits) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::is_regular_file(d.path, ec)) return "cannot read density file '" + d.path + "': not a regular file";
    const uintmax_t size = fs::file_size(d.path, ec);
    if (ec) return "cannot read density file '" + d.path + "': " + ec.message();
    std::ifstream in(d.path, std::ios::binary);
    unsigned char header[6];
    if (size < 6 || !in.read(reinterpret_cast<char*>(header), 6))
        return fmt::format("'{}' is not a df3 file: {} bytes, shorter than the 6-byte header", d.path, size);
    const int n[3] = {header[0] << 8 | header[1], header[2] << 8 | header[3], header[4] << 8 | header[5]};
    const uint64_t voxels = uint64_t(n[0]) * n[1] * n[2];
    const uint64_t body = size - 6;
    if (voxels == 0 || body % voxels != 0 || (body / voxels != 1 && body / voxels != 2 && body / voxels != 4))
        return fmt::format("'{}' is not a df3 file: {} bytes after the header for {} x {} x {} voxels (1, 2 or 4 "
                           "bytes each)",
                           d.path, body, n[0], n[1], n[2]);
    const uint64_t megabytes = (voxels * sizeof(float)) >> 20;
    if (int64_t(megabytes) > limits.memoryMB)
        return fmt::format("density file '{}' has {} x {} x {} voxels, {} MB in memory: over the limit of {} MB ({})",
                           d.path, n[0], n[1], n[2], megabytes, limits.memoryMB,
                           limitHint(limits, &Limits::memoryMB));
    const int bytes = int(body / voxels);
    std::vector<unsigned char> raw(body);
    if (!in.read(reinterpret_cast<char*>(raw.data()), std::streamsize(body)))
        return "cannot read density file '" + d.path + "': it ended early";
    const double largest = bytes == 1 ? 255.0 : bytes == 2 ? 65535.0 : 4294967295.0;
    d.nx = n[0], d.ny = n[1], d.nz = n[2];
    d.values.resize(voxels);
    for (uint64_t i = 0; i < voxels; ++i) {
        uint32_t v = 0;
        for (int b = 0; b < bytes; ++b) v = v << 8 | raw[i * bytes + b];
        d.values[i] = float(v / largest);
    }
    return "";
}

} // namespace drt
