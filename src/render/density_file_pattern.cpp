#include "render/density_file_pattern.h"

#include <algorithm>
#include <cmath>

namespace drt {

namespace {

// Catmull-Rom through p0..p3, at s in [0, 1) between p1 and p2.
double catmullRom(double p0, double p1, double p2, double p3, double s) {
    return 0.5 * (2 * p1 + (p2 - p0) * s + (2 * p0 - 5 * p1 + 4 * p2 - p3) * s * s +
                  (3 * (p1 - p2) + p3 - p0) * s * s * s);
}

int wrap(int i, int n) {
    i %= n;
    return i < 0 ? i + n : i;
}

} // namespace

double densityFileValue(const DensityFile& f, const Vec3& p) {
    if (f.values.empty() || f.nx < 1 || f.ny < 1 || f.nz < 1) return 0;
    if (!(p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 1 && p.z >= 0 && p.z < 1)) return 0; // NaN too
    const double tx = p.x * f.nx, ty = p.y * f.ny, tz = p.z * f.nz;
    const int ix = std::min(int(tx), f.nx - 1), iy = std::min(int(ty), f.ny - 1), iz = std::min(int(tz), f.nz - 1);
    const auto at = [&](int x, int y, int z) {
        return double(f.values[(size_t(wrap(z, f.nz)) * f.ny + wrap(y, f.ny)) * f.nx + wrap(x, f.nx)]);
    };
    switch (f.interpolation) {
    case DensityFile::Interpolation::None: return at(ix, iy, iz);
    case DensityFile::Interpolation::Trilinear: {
        const double sx = tx - ix, sy = ty - iy, sz = tz - iz;
        double plane[2];
        for (int k = 0; k < 2; ++k) {
            const double y0 = at(ix, iy, iz + k) + sx * (at(ix + 1, iy, iz + k) - at(ix, iy, iz + k));
            const double y1 = at(ix, iy + 1, iz + k) + sx * (at(ix + 1, iy + 1, iz + k) - at(ix, iy + 1, iz + k));
            plane[k] = y0 + sy * (y1 - y0);
        }
        return plane[0] + sz * (plane[1] - plane[0]);
    }
    case DensityFile::Interpolation::Tricubic: {
        const double sx = tx - ix, sy = ty - iy, sz = tz - iz;
        double planes[4];
        for (int k = 0; k < 4; ++k) {
            double rows[4];
            for (int j = 0; j < 4; ++j) {
                const int y = iy + j - 1, z = iz + k - 1;
                rows[j] = catmullRom(at(ix - 1, y, z), at(ix, y, z), at(ix + 1, y, z), at(ix + 2, y, z), sx);
            }
            planes[k] = catmullRom(rows[0], rows[1], rows[2], rows[3], sy);
        }
        return std::max(0.0, catmullRom(planes[0], planes[1], planes[2], planes[3], sz));
    }
    }
    return 0;
}

} // namespace drt
