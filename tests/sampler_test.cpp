// Unit tests of the samplers (src/sampling/sampler.h): determinism, range,
// the stratification each sampler promises, and the factory's errors.
#include "core/hash.h"
#include "sampling/filter.h"
#include "sampling/sampler.h"
#include "sampling/sobol.h"
#include "sampling/warp.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

namespace drt {
namespace {

using Point = std::vector<double>;

// The first `count` pixel samples of pixel (x, y), dimensions 0..4 as a camera
// reads them: pixel and lens by get2D, time by get1D.
std::vector<Point> cameraPoints(const std::string& name, int count, uint64_t seed, int x = 3, int y = 7) {
    auto sampler = makeSampler(name, count, seed);
    std::vector<Point> points;
    for (int i = 0; i < count; ++i) {
        sampler->startPixelSample(x, y, i);
        const Vec2 pixel = sampler->get2D(kDimPixel);
        const double time = sampler->get1D(kDimTime);
        const Vec2 lens = sampler->get2D(kDimLens);
        points.push_back({pixel.x, pixel.y, time, lens.x, lens.y});
    }
    return points;
}

// True if every elementary box prod_j [c_j / 2^a_j, (c_j + 1) / 2^a_j) over the
// dimensions `dims`, for every split a of `logCells` bits, holds exactly
// points.size() / 2^logCells points: the net property with t = log2(n) - logCells.
bool isNet(const std::vector<Point>& points, const std::vector<int>& dims, int logCells) {
    const size_t s = dims.size();
    const size_t expected = points.size() >> logCells;
    std::vector<int> a(s, 0);
    bool ok = true;
    std::function<void(size_t, int)> split = [&](size_t j, int left) {
        if (!ok) return;
        if (j + 1 == s) {
            a[j] = left;
            std::vector<size_t> counts(size_t(1) << logCells, 0);
            for (const Point& p : points) {
                size_t cell = 0;
                for (size_t k = 0; k < s; ++k)
                    cell = (cell << a[k]) | static_cast<size_t>(std::ldexp(p[static_cast<size_t>(dims[k])], a[k]));
                ++counts[cell];
            }
            for (size_t c : counts) ok = ok && c == expected;
            return;
        }
        for (int v = 0; v <= left; ++v) {
            a[j] = v;
            split(j + 1, left - v);
        }
    };
    split(0, logCells);
    return ok;
}

TEST(Sampler, NamesAndDefault) {
    const auto& names = samplerNames();
    for (const char* n : {"independent", "stratified", "sobol"})
        EXPECT_NE(std::find(names.begin(), names.end(), n), names.end()) << n;
    EXPECT_EQ(defaultSamplerName(), "sobol");
    for (const auto& n : names) EXPECT_EQ(makeSampler(n, 4, 0)->name(), n);
}

TEST(Sampler, FactoryRejectsBadInput) {
    EXPECT_THROW(makeSampler("halton", 4, 0), std::invalid_argument);
    EXPECT_THROW(makeSampler("sobol", 0, 0), std::invalid_argument);
    try {
        makeSampler("halton", 4, 0);
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("sobol"), std::string::npos) << "lists the accepted names";
    }
}

TEST(Sampler, DeterministicInRangeAndSeedDependent) {
    for (const auto& name : samplerNames()) {
        auto a = makeSampler(name, 16, 1234);
        auto b = makeSampler(name, 16, 1234);
        auto c = makeSampler(name, 16, 1235);
        int differing = 0;
        for (int i = 0; i < 16; ++i) {
            // Visit b in another order of dimensions: values depend on nothing but the inputs.
            a->startPixelSample(5, -2, i);
            b->startPixelSample(5, -2, i);
            c->startPixelSample(5, -2, i);
            for (int d = 40; d >= 0; --d) {
                const double vb = b->get1D(d);
                const Vec2 wb = b->get2D(d);
                const Vec2 sb = b->get2DStratified(d, i % 5, 9);
                const double va = a->get1D(d);
                const Vec2 wa = a->get2D(d);
                const Vec2 sa = a->get2DStratified(d, i % 5, 9);
                EXPECT_EQ(va, vb) << name;
                EXPECT_EQ(wa.x, wb.x) << name;
                EXPECT_EQ(wa.y, wb.y) << name;
                EXPECT_EQ(sa.x, sb.x) << name;
                EXPECT_EQ(sa.y, sb.y) << name;
                for (double v : {va, wa.x, wa.y, sa.x, sa.y}) {
                    EXPECT_GE(v, 0.0) << name;
                    EXPECT_LT(v, 1.0) << name;
                }
                differing += c->get1D(d) != va;
            }
        }
        EXPECT_GT(differing, 16 * 41 * 9 / 10) << name << ": another seed gives other values";
    }
}

TEST(Sampler, CloneGivesTheSameStream) {
    for (const auto& name : samplerNames()) {
        auto a = makeSampler(name, 8, 99);
        a->startPixelSample(1, 1, 3);
        auto b = a->clone();
        EXPECT_EQ(b->name(), name);
        EXPECT_EQ(b->samplesPerPixel(), 8);
        EXPECT_EQ(b->seed(), 99u);
        for (int i = 0; i < 8; ++i) {
            a->startPixelSample(10, 20, i);
            b->startPixelSample(10, 20, i);
            for (int d = 0; d < 30; ++d) EXPECT_EQ(a->get1D(d), b->get1D(d)) << name;
        }
    }
}

// The Sobol sampler keeps a pixel's scramble seeds in a cache by dimension:
// whatever dimensions were asked before, and in whatever order, each value is
// the one a fresh sampler gives for that dimension alone. The dimensions
// include the lights' (2048 apart past 8197, which once shared one slot) and
// more than the cache holds, so slots are shared and overwritten.
TEST(SobolSampler, ValuesDoNotDependOnWhichDimensionsWereAskedBefore) {
    std::vector<int> dimensions;
    for (int d = 0; d < 120; ++d) dimensions.push_back(d);
    for (int light = 1; light < 12; ++light)
        for (int depth = 0; depth < 3; ++depth) dimensions.push_back(8197 + 2 * ((light - 1) * 1024 + depth));
    dimensions.push_back((1 << 30) + 8197);
    for (int order = 0; order < 3; ++order) {
        auto used = makeSampler("sobol", 16, 5);
        for (int x = 0; x < 2; ++x)
            for (int i = 0; i < 16; ++i) {
                used->startPixelSample(x, 4, i);
                for (size_t n = 0; n < dimensions.size(); ++n) {
                    // forwards, backwards, and the lights interleaved with the bounces
                    const size_t k = order == 0 ? n : order == 1 ? dimensions.size() - 1 - n
                                                                 : (n * 37) % dimensions.size();
                    const int d = dimensions[k];
                    auto fresh = makeSampler("sobol", 16, 5);
                    fresh->startPixelSample(x, 4, i);
                    const bool twoD = (n + size_t(order)) % 2 == 0;
                    if (twoD) {
                        const Vec2 a = used->get2D(d), b = fresh->get2D(d);
                        ASSERT_EQ(a.x, b.x) << "dimension " << d << ", sample " << i << ", order " << order;
                        ASSERT_EQ(a.y, b.y) << "dimension " << d << ", sample " << i << ", order " << order;
                    } else {
                        ASSERT_EQ(used->get1D(d), fresh->get1D(d)) << "dimension " << d << ", sample " << i;
                    }
                    const Vec2 s = used->get2DStratified(d, 1, 4), t = fresh->get2DStratified(d, 1, 4);
                    ASSERT_EQ(s.x, t.x) << "dimension " << d;
                    ASSERT_EQ(s.y, t.y) << "dimension " << d;
                }
            }
    }
}

// A packet's camera dimensions drawn at once (getCameraDimensions) are the
// values startPixelSample, get2D(kDimPixel), get1D(kDimTime) and
// get2D(kDimLens) give one sample at a time, for every sampler, sample count,
// packet start and choice of time and lens, and drawing them changes no value
// drawn after (the pixel's other dimensions, the next pixel's).
TEST(Sampler, CameraDimensionsOfAPacketAreThoseOfEachSample) {
    const auto same = [](double a, double b) { return std::bit_cast<uint64_t>(a) == std::bit_cast<uint64_t>(b); };
    for (const std::string& name : samplerNames())
        for (const int spp : {1, 3, 8, 16, 100, 300})
            for (int effects = 0; effects < 4; ++effects) {
                const bool withTime = effects & 1, withLens = effects & 2;
                auto batch = makeSampler(name, spp, 11);
                auto single = makeSampler(name, spp, 11);
                for (const auto& [x, y] : {std::pair{0, 0}, std::pair{5, 2}, std::pair{5, 3}, std::pair{-4, 9}})
                    for (int first = 0; first < spp; first += 8) {
                        const int count = std::min(8, spp - first - (first % 3 == 1 ? 1 : 0));
                        Vec2 pixel[8], lens[8];
                        double time[8];
                        batch->getCameraDimensions(x, y, first, count, pixel, withTime ? time : nullptr,
                                                   withLens ? lens : nullptr);
                        for (int j = 0; j < count; ++j) {
                            single->startPixelSample(x, y, first + j);
                            const Vec2 p = single->get2D(kDimPixel);
                            const int px = x, py = y; // clang 14 cannot capture structured bindings
                            const auto where = [&] {
                                return name + " spp " + std::to_string(spp) + " effects " + std::to_string(effects) +
                                       " pixel " + std::to_string(px) + "," + std::to_string(py) + " sample " +
                                       std::to_string(first + j);
                            };
                            ASSERT_TRUE(same(pixel[j].x, p.x) && same(pixel[j].y, p.y)) << where();
                            if (withTime) {
                                ASSERT_TRUE(same(time[j], single->get1D(kDimTime))) << where();
                            }
                            if (withLens) {
                                const Vec2 l = single->get2D(kDimLens);
                                ASSERT_TRUE(same(lens[j].x, l.x) && same(lens[j].y, l.y)) << where();
                            }
                        }
                        // The rest of each sample afterwards, as the renderer draws it.
                        for (int j = 0; j < count; ++j) {
                            batch->startPixelSample(x, y, first + j);
                            single->startPixelSample(x, y, first + j);
                            for (const int d : {kDimPixel, kDimLens, kDimFirstBounce, 8197}) {
                                const Vec2 a = batch->get2D(d), b = single->get2D(d);
                                ASSERT_EQ(a.x, b.x) << name << " dimension " << d;
                                ASSERT_EQ(a.y, b.y) << name << " dimension " << d;
                            }
                            ASSERT_EQ(batch->get1D(kDimTime), single->get1D(kDimTime)) << name;
                        }
                    }
            }
}

TEST(Sampler, PixelsAreDecorrelated) {
    // The same sample index in neighbouring pixels must not repeat a value.
    for (const auto& name : samplerNames()) {
        auto s = makeSampler(name, 16, 5);
        s->startPixelSample(0, 0, 0);
        const double a = s->get1D(0);
        s->startPixelSample(1, 0, 0);
        const double b = s->get1D(0);
        s->startPixelSample(0, 1, 0);
        const double c = s->get1D(0);
        EXPECT_NE(a, b) << name;
        EXPECT_NE(a, c) << name;
    }
}

TEST(StratifiedSampler, OneSamplePerCellForSquareCounts) {
    for (int n : {2, 3, 5, 8}) {
        const auto points = cameraPoints("stratified", n * n, 17);
        for (int pair : {0, 3}) { // pixel and lens
            std::vector<int> cells(static_cast<size_t>(n * n), 0);
            for (const Point& p : points)
                ++cells[static_cast<size_t>(int(p[size_t(pair)] * n) + n * int(p[size_t(pair) + 1] * n))];
            for (int c : cells) EXPECT_EQ(c, 1) << "n=" << n << " dims " << pair;
        }
        std::vector<int> strata(static_cast<size_t>(n * n), 0); // time: 1D strata
        for (const Point& p : points) ++strata[static_cast<size_t>(p[2] * n * n)];
        for (int c : strata) EXPECT_EQ(c, 1);
    }
}

TEST(SobolSampler, PixelDimensionsAreA0m2Net) {
    for (int m = 1; m <= 10; ++m) {
        const auto points = cameraPoints("sobol", 1 << m, 2024 + uint64_t(m));
        EXPECT_TRUE(isNet(points, {0, 1}, m)) << "m=" << m;
    }
}

TEST(SobolSampler, PixelAndTimeAreJointlyStratified) {
    // Sobol dimensions 0-2 (polynomials of degrees 1, 1, 2) form a (1,m,3)-net:
    // every elementary box of volume 2^(1-m) holds exactly two points.
    for (int m = 2; m <= 10; ++m) {
        const auto points = cameraPoints("sobol", 1 << m, 7 * uint64_t(m));
        EXPECT_TRUE(isNet(points, {0, 1, 2}, m - 1)) << "m=" << m;
        EXPECT_TRUE(isNet(points, {2}, m)) << "time alone is a (0,m,1)-net";
    }
}

TEST(SobolSampler, PixelAndLensAreJointlyStratified) {
    // Dimensions 0, 1, 3, 4 (degrees 1, 1, 3, 3): t <= 0 + 0 + 2 + 2 = 4.
    for (int m = 4; m <= 10; ++m) {
        const auto points = cameraPoints("sobol", 1 << m, 11 * uint64_t(m));
        EXPECT_TRUE(isNet(points, {0, 1, 3, 4}, m - 4)) << "m=" << m;
        EXPECT_TRUE(isNet(points, {3, 4}, m - 4)) << "lens alone, m=" << m;
    }
}

TEST(SobolSampler, PaddedPairsAreNetsToo) {
    // A per-bounce 2D dimension: a scrambled (0,2)-sequence per pixel.
    const int m = 8;
    auto s = makeSampler("sobol", 1 << m, 3);
    std::vector<Point> points;
    for (int i = 0; i < (1 << m); ++i) {
        s->startPixelSample(4, 4, i);
        const Vec2 v = s->get2D(bounceDimension(1, kOffsetLobe));
        points.push_back({v.x, v.y, s->get1D(bounceDimension(0, kOffsetLightChoice))});
    }
    EXPECT_TRUE(isNet(points, {0, 1}, m));
    EXPECT_TRUE(isNet(points, {2}, m));
}

TEST(SobolSampler, StratifiedLightPointsAreNets) {
    // count = 16 points per pixel sample form a (0,4,2)-net; all 16 x 16 of the
    // pixel's points form a (0,8,2)-net.
    auto s = makeSampler("sobol", 16, 8);
    std::vector<Point> all;
    const int dim = bounceDimension(0, kOffsetLight);
    for (int i = 0; i < 16; ++i) {
        s->startPixelSample(2, 3, i);
        std::vector<Point> one;
        for (int k = 0; k < 16; ++k) {
            const Vec2 v = s->get2DStratified(dim, k, 16);
            one.push_back({v.x, v.y});
            all.push_back({v.x, v.y});
        }
        EXPECT_TRUE(isNet(one, {0, 1}, 4)) << "sample " << i;
    }
    EXPECT_TRUE(isNet(all, {0, 1}, 8));
}

TEST(Samplers, StratifiedRunsAreThePointsOneByOne) {
    // get2DStratifiedRun(d, count, out): out[k] is get2DStratified(d, k, count)
    // bit for bit, for every sampler, with the per-pixel caches warm or cold
    // (a fresh sampler for each way), at sample indices past 256 (the
    // shuffle's table) and for counts that are and are not powers of two.
    for (const std::string name : {"sobol", "independent", "stratified"}) {
        auto byOne = makeSampler(name, 1024, 21), byRun = makeSampler(name, 1024, 21);
        for (const int index : {0, 5, 300, 1023})
            for (const int count : {1, 2, 3, 8, 64, 256})
                for (const int d : {bounceDimension(0, kOffsetLight), bounceDimension(2, kOffsetLight), 70001}) {
                    byOne->startPixelSample(4, 7, index);
                    byRun->startPixelSample(4, 7, index);
                    std::vector<Vec2> run(size_t(count), Vec2{-1, -1});
                    byRun->get2DStratifiedRun(d, count, run.data());
                    for (int k = 0; k < count; ++k) {
                        const Vec2 one = byOne->get2DStratified(d, k, count);
                        ASSERT_EQ(std::bit_cast<uint64_t>(one.x), std::bit_cast<uint64_t>(run[size_t(k)].x))
                            << name << " index " << index << " count " << count << " k " << k;
                        ASSERT_EQ(std::bit_cast<uint64_t>(one.y), std::bit_cast<uint64_t>(run[size_t(k)].y));
                    }
                }
    }
}

TEST(BaseSampler, StratifiedLightPointsFillTheGrid) {
    // The default get2DStratified: one point per cell of the near-square grid.
    auto s = makeSampler("independent", 1, 4);
    s->startPixelSample(0, 0, 0);
    std::vector<int> cells(12, 0);
    for (int k = 0; k < 12; ++k) {
        const Vec2 v = s->get2DStratified(9, k, 12); // 3 x 4 cells
        ++cells[static_cast<size_t>(int(v.x * 3) + 3 * int(v.y * 4))];
    }
    for (int c : cells) EXPECT_EQ(c, 1);
}

TEST(Owen, ScrambleIsABijectionKeepingPrefixes) {
    // Nested uniform scrambling: values sharing their top k bits still share
    // them afterwards (the digit flips depend only on the digits above).
    for (uint32_t seed : {0u, 1u, 0xdeadbeefu}) {
        for (uint32_t v = 0; v < 4096; v += 7) {
            const uint32_t a = v << 20, b = (v << 20) | 0x000fffffu;
            EXPECT_EQ(owenScramble(a, seed) >> 20, owenScramble(b, seed) >> 20);
        }
        std::vector<bool> seen(1 << 12, false);
        for (uint32_t v = 0; v < (1u << 12); ++v) seen[owenScramble(v << 20, seed) >> 20] = true;
        EXPECT_EQ(std::count(seen.begin(), seen.end(), true), 1 << 12);
    }
}

// Every image depends on the Sobol sampler's values to the bit (the exact
// goldens, the determinism tests), so a faster sampler must give the same
// ones: a digest of its values over sample counts, seeds, pixels, every kind
// of request and dimensions from the camera's to the lights' (8197 on), with
// sequence indices past 2^8 and 2^16 (get2DStratified's count * spp), taken
// from the sampler as it was before it was tuned (2026-12-03).
TEST(SobolSampler, ValuesAreThoseOfTheReferenceSampler) {
    uint64_t digest = 0x243f6a8885a308d3ULL;
    const auto mixIn = [&](double v) { digest = hashValues({digest, std::bit_cast<uint64_t>(v)}); };
    for (const int spp : {1, 5, 16, 64, 1024})
        for (const uint64_t seed : {0ull, 7ull, 0xfedcba9876543210ull})
            for (const auto& [x, y] : {std::pair{0, 0}, std::pair{13, -4}, std::pair{1000, 77}}) {
                auto sampler = makeSampler("sobol", spp, seed);
                for (int i = 0; i < std::min(spp, 40); ++i) {
                    sampler->startPixelSample(x, y, spp > 40 ? i * (spp / 40) + 1 : i);
                    for (const int d : {0, 1, 2, 3, 4, 5, 6, 7, 12, 13, 21, 40, 8197, 8199, 10245, 1 << 29}) {
                        mixIn(sampler->get1D(d));
                        const Vec2 w = sampler->get2D(d);
                        mixIn(w.x), mixIn(w.y);
                        for (const int count : {4, 289, 70000}) {
                            const Vec2 s = sampler->get2DStratified(d, count - 1 - i % count, count);
                            mixIn(s.x), mixIn(s.y);
                        }
                    }
                }
            }
    EXPECT_EQ(digest, 0xbf0c22d523e8acc3ull);
}

// The direction numbers' XOR over the index bits, as the Sobol construction
// defines it, against the tables sobolValue reads, on random indices.
TEST(Sobol, ValuesAreTheXorOfTheDirectionNumbers) {
    uint64_t state = 12345;
    for (int n = 0; n < 20000; ++n) {
        state = mix64(state + 1);
        const auto index = static_cast<uint32_t>(n < 1000 ? uint64_t(n) : state >> (state & 31));
        for (int d = 0; d < kSobolDimensions; ++d) {
            uint32_t expected = 0;
            for (int j = 0; j < 32; ++j)
                if ((index >> j) & 1u) expected ^= sobol_detail::kDirections[size_t(d)][size_t(j)];
            ASSERT_EQ(sobolValue(index, d), expected) << "index " << index << ", dimension " << d;
            // The scrambled value, by the plain composition of its definition.
            const OwenSeed seed(static_cast<uint32_t>(state >> 32));
            ASSERT_EQ(owenScrambledSobol(index, d, seed), owenScramble(expected, seed.seed))
                << "index " << index << ", dimension " << d;
        }
        // The byte reversal table the sampler's shuffle reads for up to 256 samples.
        ASSERT_EQ(uint32_t(sobol_detail::kReversedByte[index & 255u]) << 24, sobol_detail::reverseBits(index & 255u));
        ASSERT_EQ(sobol_detail::kReversedByte[index >> 24], sobol_detail::reverseBits(index) & 255u);
    }
}

// Sixteen samples at once (jointLanes: AVX2 where the processor has it) against
// the one-sample functions lane by lane (jointLanesScalar), on random seeds,
// shuffle masks, indices of every size and every choice of dimensions.
TEST(Sobol, SixteenLanesAreTheOneSampleValues) {
    uint64_t state = 977;
    const auto next = [&] { return state = mix64(state + 0x9e3779b97f4a7c15ULL); };
    for (int n = 0; n < 20000; ++n) {
        const int maskBits = int(next() % 33);
        const uint32_t mask = maskBits == 32 ? ~0u : (1u << maskBits) - 1u;
        uint32_t index[sobol_detail::kLanes];
        for (int lane = 0; lane < sobol_detail::kLanes; ++lane) {
            const uint64_t r = next();
            // Small indices (a pixel's usual samples), then any 32-bit value.
            index[lane] = static_cast<uint32_t>(n < 5000 ? (r & 255u) >> (r >> 60) : r >> (r & 31));
        }
        const OwenSeed shuffle(static_cast<uint32_t>(next()));
        OwenSeed seeds[kSobolDimensions];
        for (OwenSeed& seed : seeds) seed = OwenSeed(static_cast<uint32_t>(next() >> 32));
        const unsigned dimensions = static_cast<unsigned>(next() % 32);
        uint32_t joint[sobol_detail::kLanes], expectedJoint[sobol_detail::kLanes];
        uint32_t values[kSobolDimensions][sobol_detail::kLanes]{}, expected[kSobolDimensions][sobol_detail::kLanes]{};
        sobol_detail::jointLanes(index, mask, shuffle, seeds, dimensions, joint, values);
        sobol_detail::jointLanesScalar(index, mask, shuffle, seeds, dimensions, expectedJoint, expected);
        for (int lane = 0; lane < sobol_detail::kLanes; ++lane) {
            ASSERT_EQ(joint[lane], expectedJoint[lane]) << "index " << index[lane] << " mask " << mask;
            for (int d = 0; d < kSobolDimensions; ++d)
                if ((dimensions >> d) & 1u) {
                    ASSERT_EQ(values[d][lane], expected[d][lane]) << "index " << index[lane] << " dimension " << d;
                }
        }
    }
}

// Eight points of a stratified run at once (runLanes: AVX2 where the processor
// has it) against runLanesScalar, and both against the definitions: point k of
// the run from base is (owenScramble(sobolValue(base | offset | k, 0)),
// owenScramble(sobolValue(base | offset | k, 1))) with the two seeds.
TEST(Sobol, RunLanesAreTheStratifiedRunsPoints) {
    uint64_t state = 4099;
    const auto next = [&] { return state = mix64(state + 0x9e3779b97f4a7c15ULL); };
    for (int n = 0; n < 20000; ++n) {
        const int countBits = 3 + int(next() % 6); // runs of 8 to 256 points
        const uint32_t count = 1u << countBits;
        const uint64_t r = next();
        const uint32_t base = static_cast<uint32_t>((n < 5000 ? (r & 255u) : r >> 33) << countBits);
        const int offset = int(next() % (count / sobol_detail::kRunLanes)) * sobol_detail::kRunLanes;
        const OwenSeed seed0(static_cast<uint32_t>(next())), seed1(static_cast<uint32_t>(next() >> 32));
        const uint32_t reversed1 = sobol_detail::sobolReversed(base, 1);
        uint32_t first[sobol_detail::kRunLanes], second[sobol_detail::kRunLanes];
        uint32_t expectedFirst[sobol_detail::kRunLanes], expectedSecond[sobol_detail::kRunLanes];
        sobol_detail::runLanes(base | uint32_t(offset), reversed1, offset, seed0, seed1, first, second);
        sobol_detail::runLanesScalar(base | uint32_t(offset), reversed1, offset, seed0, seed1, expectedFirst,
                                     expectedSecond);
        for (int k = 0; k < sobol_detail::kRunLanes; ++k) {
            const uint32_t i = base | uint32_t(offset + k);
            ASSERT_EQ(first[k], expectedFirst[k]) << "base " << base << " k " << offset + k;
            ASSERT_EQ(second[k], expectedSecond[k]) << "base " << base << " k " << offset + k;
            ASSERT_EQ(expectedFirst[k], owenScramble(sobolValue(i, 0), seed0.seed)) << "base " << base;
            ASSERT_EQ(expectedSecond[k], owenScramble(sobolValue(i, 1), seed1.seed)) << "base " << base;
        }
    }
}

// The reference itself: for masks of a power-of-two sample count, the
// shuffled index is the sampler's own (its one-sample draws), and the values
// are the definitions composed in full (owenScramble of sobolValue).
TEST(Sobol, TheOneSampleLanesAreTheSamplersShuffleAndValues) {
    for (const int spp : {1, 2, 16, 256, 1024}) {
        const uint32_t mask = uint32_t(spp) - 1u;
        const OwenSeed shuffle(0x1234567u), seeds[kSobolDimensions] = {OwenSeed(1), OwenSeed(2), OwenSeed(3),
                                                                        OwenSeed(4), OwenSeed(5)};
        for (uint32_t first = 0; first < uint32_t(spp); first += sobol_detail::kLanes) {
            uint32_t index[sobol_detail::kLanes], joint[sobol_detail::kLanes], values[kSobolDimensions][sobol_detail::kLanes];
            for (int lane = 0; lane < sobol_detail::kLanes; ++lane) index[lane] = first + uint32_t(lane);
            sobol_detail::jointLanesScalar(index, mask, shuffle, seeds, 0b11111u, joint, values);
            for (int lane = 0; lane < sobol_detail::kLanes; ++lane) {
                const uint32_t i = index[lane];
                const uint32_t expectedJoint = (i & ~mask) | (owenScramble(i, shuffle.seed) & mask);
                ASSERT_EQ(joint[lane], expectedJoint);
                if (i < uint32_t(spp)) {
                    ASSERT_LT(joint[lane], uint32_t(spp)) << "a shuffle within the pixel's samples";
                }
                for (int d = 0; d < kSobolDimensions; ++d)
                    ASSERT_EQ(values[d][lane], owenScramble(sobolValue(expectedJoint, d), seeds[d].seed));
            }
        }
    }
}

// The sampler drawing a packet's camera dimensions sixteen at a time gives the
// values of the one drawing them one sample at a time, and leaves the same
// state behind (the next draws of the pixel agree too).
TEST(SobolSampler, CameraDimensionsInLanesAreThoseOneByOne) {
    const auto same = [](double a, double b) { return std::bit_cast<uint64_t>(a) == std::bit_cast<uint64_t>(b); };
    for (const int spp : {1, 5, 16, 64, 1000})
        for (int effects = 0; effects < 4; ++effects) {
            const auto lanes = makeSobolSampler(spp, 2024, true)->clone(), oneByOne = makeSobolSampler(spp, 2024, false);
            for (const auto& [x, y] : {std::pair{0, 0}, std::pair{7, 1}, std::pair{-3, 12}})
                for (int first = 0; first < spp; first += 11) {
                    // Packets of 11 (one group of sixteen serves parts of two),
                    // asking for time and lens in turn (a group worked out
                    // without them cannot serve a packet that asks).
                    const int count = std::min(11, spp - first), asked = (effects + first / 11) % 4;
                    const bool withTime = asked & 1, withLens = asked & 2;
                    Vec2 pixel[2][11], lens[2][11];
                    double time[2][11];
                    lanes->getCameraDimensions(x, y, first, count, pixel[0], withTime ? time[0] : nullptr,
                                               withLens ? lens[0] : nullptr);
                    oneByOne->getCameraDimensions(x, y, first, count, pixel[1], withTime ? time[1] : nullptr,
                                                  withLens ? lens[1] : nullptr);
                    for (int j = 0; j < count; ++j) {
                        ASSERT_TRUE(same(pixel[0][j].x, pixel[1][j].x) && same(pixel[0][j].y, pixel[1][j].y))
                            << "spp " << spp << " sample " << first + j;
                        if (withTime) {
                            ASSERT_TRUE(same(time[0][j], time[1][j]));
                        }
                        if (withLens) {
                            ASSERT_TRUE(same(lens[0][j].x, lens[1][j].x) && same(lens[0][j].y, lens[1][j].y));
                        }
                    }
                    for (int j = 0; j < count; ++j) {
                        lanes->startPixelSample(x, y, first + j);
                        oneByOne->startPixelSample(x, y, first + j);
                        for (const int d : {kDimPixel, kDimTime, kDimLens, kDimFirstBounce, 8197}) {
                            const Vec2 a = lanes->get2D(d), b = oneByOne->get2D(d);
                            ASSERT_TRUE(same(a.x, b.x) && same(a.y, b.y)) << "dimension " << d;
                        }
                    }
                }
        }
}

// Quick checks of the warps and filters; the chi-square tests are in tests/statistical.
TEST(Warp, MapsIntoTheirDomains) {
    for (int i = 0; i < 64; ++i) {
        const Vec2 u{(i % 8 + 0.5) / 8.0, (i / 8 + 0.25) / 8.0};
        const Vec2 d = squareToConcentricDisc(u);
        EXPECT_LE(d.x * d.x + d.y * d.y, 1.0 + 1e-12);
        const Vec3 c = squareToCosineHemisphere(u);
        EXPECT_NEAR(length(c), 1.0, 1e-12);
        EXPECT_GE(c.z, 0.0);
        const Vec3 axis = normalize(Vec3{1, -2, 0.5});
        const Vec3 g = sampleLobeAround(axis, 20.0, u);
        EXPECT_NEAR(length(g), 1.0, 1e-12);
        EXPECT_GT(dot(g, axis), 0.0);
        const Vec3 w = sampleCosineAround(axis, u);
        EXPECT_NEAR(length(w), 1.0, 1e-12);
        EXPECT_NEAR(dot(w, axis), c.z, 1e-12); // the hemisphere's z becomes the axis
    }
    EXPECT_EQ(squareToConcentricDisc({0.5, 0.5}).x, 0.0);
    EXPECT_EQ(phongLobePdf(-0.1, 5), 0.0);
    EXPECT_NEAR(phongLobePdf(1.0, 5), 6.0 / (2 * kPi), 1e-15);
}

TEST(Warp, SphericalRectangleSolidAngleAndDegenerateCases) {
    // A unit square seen from its centre's normal at height 1: solid angle
    // 4 asin(1/5) (van Oosterom & Strackee for a rectangle a x b at distance d:
    // 4 asin(ab / sqrt((a^2 + 4d^2)(b^2 + 4d^2)))).
    const SphericalRectangle r({0, 0, 0}, {-0.5, -0.5, 1}, {1, 0, 0}, {0, 1, 0});
    ASSERT_TRUE(r.valid());
    EXPECT_NEAR(r.solidAngle(), 4 * std::asin(1.0 / 5.0), 1e-12);
    const Vec3 p = r.sample({0.3, 0.8});
    EXPECT_NEAR(p.z, 1.0, 1e-12);
    const SphericalRectangle inPlane({3, 0, 1}, {-0.5, -0.5, 1}, {1, 0, 0}, {0, 1, 0});
    EXPECT_FALSE(inPlane.valid());
    EXPECT_EQ(inPlane.pdf(), 0.0);
}

TEST(Filter, NamesSupportAndErrors) {
    EXPECT_EQ(defaultFilterName(), "box");
    for (const auto& n : filterNames()) {
        const Filter f = makeFilter(n);
        EXPECT_EQ(filterName(f), n);
        for (int i = 0; i < 100; ++i) {
            const Vec2 o = sampleFilter(f, {i / 100.0, (99 - i) / 100.0});
            EXPECT_LE(std::fabs(o.x), f.radius);
            EXPECT_LE(std::fabs(o.y), f.radius);
        }
    }
    EXPECT_THROW(makeFilter("mitchell"), std::invalid_argument);
    const Vec2 centre = sampleFilter(makeFilter("gaussian"), {0.5, 0.5});
    EXPECT_NEAR(centre.x, 0.0, 1e-12);
}

} // namespace
} // namespace drt
