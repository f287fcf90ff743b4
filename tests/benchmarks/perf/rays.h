// drt_perf rays: how close drt's ray rate comes to raw Embree's. The same
// scenes (rays_scene.h: plane + 10 spheres; plane + a ~1M-triangle mesh) and
// the same ray mixes (camera rays only; camera rays + one shadow ray per hit
// facing a point light) are traced by raw Embree (rays_embree.h: single rays
// and 8/16-wide packets) and rendered by each drt (`drt render --stats`), in
// one run, repetitions interleaved. See docs/performance.md.
#pragma once

#include "perf.h"

#include <iosfwd>
#include <string>
#include <vector>

namespace drt::perf {

struct RaysOptions {
    std::string outputDir;
    std::vector<DrtBinary> drt;
    std::vector<std::string> scenes = {"spheres", "mesh"};
    int width = 1024, height = 768, spp = 16, threads = 2;
    int repetitions = 0; // 0: 5
    int triangles = 1000000;
};

// Writes rays.csv and rays.md into outputDir; the table also goes to `log`.
int runRays(const RaysOptions& options, std::ostream& log);

} // namespace drt::perf
