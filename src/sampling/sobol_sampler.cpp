// The "sobol" sampler: Owen-scrambled Sobol points, the default.
//
// Dimensions 0-4 (pixel, time, lens) are the five coordinates of ONE Sobol
// point per pixel sample, so pixel x time and pixel x lens stay stratified
// jointly: a motion-blurred or defocused edge converges like a still one
// (docs/effects.md, "Association of ray ids"). Dimensions 5 and up (per
// bounce) are padded: each 2D request is its own scrambled (0,2)-sequence (Sobol dimensions 0 and 1)
// and each 1D request its own scrambled van der Corput sequence, with the
// sample order shuffled independently per dimension so the pairs are
// decorrelated from each other and from the camera dimensions.
//
// Per pixel, the sample index is shuffled by a nested uniform scramble of its
// bits (Burley 2020, section 4): the first 2^k indices still map to an aligned
// block of 2^k Sobol points, so every power-of-two prefix stays a net.
#include "core/hash.h"
#include "sampling/sobol.h"

#include <algorithm>

namespace drt {
namespace {

class SobolSampler final : public Sampler {
public:
    // lanes: see makeSobolSampler; only where the processor runs the AVX2
    // lanes (elsewhere one by one is the cheaper way to the same values).
    SobolSampler(int spp, uint64_t seed, bool lanes)
        : Sampler(spp, seed), lanes_(lanes && sobol_detail::haveJointLanes()) {
        // The shuffle permutes the low `bits` bits: enough for every index < spp.
        int bits = 0;
        while (bits < 31 && (1u << bits) < static_cast<uint32_t>(spp)) ++bits;
        mask_ = (1u << bits) - 1u;
    }
    // A fresh sampler: the per-pixel cache is not copied.
    std::unique_ptr<Sampler> clone() const override {
        return std::make_unique<SobolSampler>(samplesPerPixel_, seed_, lanes_);
    }

    void startPixelSample(int x, int y, int index) override {
        startPixel(x, y);
        index_ = index;
        // The renderer starts each sample twice (its camera ray in a packet
        // with the pixel's next samples, then the rest): the shuffle is kept.
        jointIndex_ = recentJointIndex(index);
    }

    // A packet's camera values in one loop: no call per sample, and the
    // samples' scrambles (chains of multiplies) independent of each other.
    void getCameraDimensions(int x, int y, int first, int count, Vec2* pixel, double* time, Vec2* lens) override {
        startPixel(x, y);
        // Time's and the lens's seeds, made once for the pixel when asked.
        for (int d = kDimTime; d < kSobolDimensions; ++d)
            if (d == kDimTime ? time != nullptr : lens != nullptr) jointSeed(d);
        // Sixteen at a time where a packet is big enough to pay for them (one
        // or two samples are cheaper one by one) or the pixel's next ones are
        // already worked out.
        if (lanes_ && (count >= kLanesFrom || aheadHolds(first, count, cameraDimensionBits(time, lens)))) {
            cameraLanes(first, count, pixel, time, lens);
            return;
        }
        if (time && lens) cameraDimensions<true, true>(first, count, pixel, time, lens);
        else if (time) cameraDimensions<true, false>(first, count, pixel, time, lens);
        else if (lens) cameraDimensions<false, true>(first, count, pixel, time, lens);
        else cameraDimensions<false, false>(first, count, pixel, time, lens);
    }

    double get1D(int dimension) override {
        if (dimension < kSobolDimensions) return joint(dimension);
        const Seeds& s = seeds(kTagPadded1D, dimension);
        return fractionToUnit(scrambledSobol0(shuffledIndex(s.shuffle), s.seed[0]));
    }

    Vec2 get2D(int dimension) override {
        if (dimension + 1 < kSobolDimensions) return {joint(dimension), joint(dimension + 1)};
        if (dimension < kSobolDimensions) return {joint(dimension), get1D(dimension + 1)};
        const Seeds& s = seeds(kTagPadded2D, dimension);
        return padded2D(shuffledIndex(s.shuffle), s);
    }

    // The k-th of `count` points: sequence index shuffled(pixel sample) * count + k
    // of a scrambled (0,2)-sequence, so the count points of one pixel sample
    // form a (0,m,2)-net when count is a power of two, and all spp * count
    // points of the pixel do too when spp is a power of two as well.
    Vec2 get2DStratified(int dimension, int k, int count) override {
        const Seeds& s = seeds(kTagStratified, dimension);
        const uint64_t base = shuffledIndex(s.shuffle);
        const auto i = static_cast<uint32_t>(base * static_cast<uint64_t>(std::max(count, 1)) + uint64_t(k));
        return padded2D(i, s);
    }

    // The same points with the seeds and the shuffled sample index looked up
    // once. For a power-of-two count up to 256 the indices base + k are base | k
    // (base is a multiple of count), and a Sobol value is the XOR of the
    // direction numbers of its index's set bits: dimension 1's reversed value
    // is base's XOR k's, k's from the first byte's table. The same values,
    // without a table walk per point.
    void get2DStratifiedRun(int dimension, int count, Vec2* out) override {
        const Seeds& s = seeds(kTagStratified, dimension);
        const uint64_t base = shuffledIndex(s.shuffle) * static_cast<uint64_t>(std::max(count, 1));
        const auto index = static_cast<uint32_t>(base);
        if (count > 0 && count <= 256 && (count & (count - 1)) == 0) {
            using namespace sobol_detail;
            const uint32_t reversed1 = sobolReversed(index, 1);
            const auto& firstByte = kReversedBytes[0][0];
            if (lanes_ && count >= kRunLanes) { // eight points at a time (sobol_detail::runLanes)
                uint32_t first[kRunLanes], second[kRunLanes];
                for (int offset = 0; offset < count; offset += kRunLanes) {
                    runLanes(index | uint32_t(offset), reversed1, offset, s.seed[0], s.seed[1], first, second);
                    for (int k = 0; k < kRunLanes; ++k)
                        out[offset + k] = {fractionToUnit(first[k]), fractionToUnit(second[k])};
                }
                return;
            }
            for (int k = 0; k < count; ++k)
                out[k] = {fractionToUnit(scrambledSobol0(index | uint32_t(k), s.seed[0])),
                          fractionToUnit(reverseBits(scrambleReversed(reversed1 ^ firstByte[size_t(k)], s.seed[1])))};
            return;
        }
        for (int k = 0; k < count; ++k) out[k] = padded2D(static_cast<uint32_t>(base + uint64_t(k)), s);
    }

    std::string name() const override { return "sobol"; }

private:
    void startPixel(int x, int y) {
        if (!havePixel_ || x != x_ || y != y_) {
            // Everything below that depends on the pixel alone is computed
            // once per pixel, not once per sample.
            x_ = x;
            y_ = y;
            havePixel_ = true;
            pixelKey_ = hashValues({seed_, uint64_t(int64_t(x)), uint64_t(int64_t(y)), 0x50b01ULL});
            jointShuffle_ = OwenSeed(static_cast<uint32_t>(key(kTagJoint, 0) >> 32));
            // The pixel position's seeds now; time's and the lens's when asked
            // (a scene without motion blur or focal blur never asks).
            for (int d = 0; d < 2; ++d) jointSeeds_[d] = OwenSeed(seed32(kTagJoint, d, 0));
            jointSeedsReady_ = 0b11u;
            ++generation_;
            for (Recent& r : recent_) r.index = -1;
        }
    }
    // One loop per choice of effects: a still pinhole camera's has nothing else.
    template <bool kTime, bool kLens>
    void cameraDimensions(int first, int count, Vec2* pixel, double* time, Vec2* lens) {
        for (int j = 0; j < count; ++j) {
            const uint32_t i = recentJointIndex(first + j);
            pixel[j] = {fractionToUnit(scrambledSobol0(i, jointSeeds_[0])),
                        fractionToUnit(owenScrambledSobol(i, 1, jointSeeds_[1]))};
            if constexpr (kTime) time[j] = fractionToUnit(owenScrambledSobol(i, kDimTime, jointSeeds_[kDimTime]));
            if constexpr (kLens)
                lens[j] = {fractionToUnit(owenScrambledSobol(i, kDimLens, jointSeeds_[kDimLens])),
                           fractionToUnit(owenScrambledSobol(i, kDimLens + 1, jointSeeds_[kDimLens + 1]))};
        }
    }
    // The same, sixteen samples at a time (sobol_detail::jointLanes): a
    // packet of eight and the pixel's next eight, which are kept for the next
    // packet. Each sample's joint index is kept for startPixelSample as
    // recentJointIndex keeps it.
    static unsigned cameraDimensionBits(const double* time, const Vec2* lens) {
        return 0b11u | (time ? 1u << kDimTime : 0u) | (lens ? 0b11u << kDimLens : 0u);
    }
    // Whether ahead_ holds samples first..first+count-1 of this pixel in these dimensions.
    bool aheadHolds(int first, int count, unsigned dimensions) const {
        return ahead_.generation == generation_ && ahead_.first <= first &&
               (ahead_.dimensions & dimensions) == dimensions && first + count <= ahead_.first + sobol_detail::kLanes;
    }
    void cameraLanes(int first, int count, Vec2* pixel, double* time, Vec2* lens) {
        using sobol_detail::kLanes;
        const unsigned dimensions = cameraDimensionBits(time, lens);
        for (int start = 0; start < count;) {
            const int sample = first + start;
            if (!aheadHolds(sample, 1, dimensions)) {
                uint32_t index[kLanes];
                for (int j = 0; j < kLanes; ++j) index[j] = static_cast<uint32_t>(sample + j);
                sobol_detail::jointLanes(index, mask_, jointShuffle_, jointSeeds_, dimensions, ahead_.joint,
                                         ahead_.values);
                ahead_.generation = generation_;
                ahead_.first = sample;
                ahead_.dimensions = dimensions;
            }
            const int from = sample - ahead_.first, n = std::min(count - start, kLanes - from);
            for (int j = 0; j < n; ++j) {
                const int k = start + j, lane = from + j;
                Recent& r = recent_[static_cast<unsigned>(first + k) % kRecent];
                r.index = first + k;
                r.jointIndex = ahead_.joint[lane];
                const auto& v = ahead_.values;
                pixel[k] = {fractionToUnit(v[0][lane]), fractionToUnit(v[1][lane])};
                if (time) time[k] = fractionToUnit(v[kDimTime][lane]);
                if (lens) lens[k] = {fractionToUnit(v[kDimLens][lane]), fractionToUnit(v[kDimLens + 1][lane])};
            }
            start += n;
        }
    }
    // The joint (shuffled) index of sample `index` of the current pixel, kept
    // for the pixel's last kRecent sample indices.
    uint32_t recentJointIndex(int index) {
        Recent& r = recent_[static_cast<unsigned>(index) % kRecent];
        if (r.index != index) {
            r.index = index;
            r.jointIndex = shuffledIndex(static_cast<uint32_t>(index), jointShuffle_);
        }
        return r.jointIndex;
    }

    static constexpr uint64_t kTagJoint = 1, kTagPadded1D = 2, kTagPadded2D = 3, kTagStratified = 4;
    static constexpr int kTags = 5;

    // The per-(pixel, tag, dimension) scramble seeds: the sample-order shuffle
    // and the Owen scramble of each component.
    struct Seeds {
        uint64_t generation = 0; // the pixel they were computed for
        int dimension = -1;
        OwenSeed shuffle;
        OwenSeed seed[2];
    };
    // A direct-mapped cache by dimension: a pixel's samples ask for the same
    // dimensions over and over. The slot is a multiplicative hash of the
    // dimension, not its low bits: the lights after the first have dimensions
    // 2048 apart (lighting.h), which low bits would put in one slot, so that
    // every light of a many-light scene evicted the others' seeds.
    static constexpr int kCacheBits = 6, kCacheSlots = 1 << kCacheBits;
    static unsigned cacheSlot(int dimension) {
        return (static_cast<uint32_t>(dimension) * 0x9e3779b1u) >> (32 - kCacheBits);
    }
    const Seeds& seeds(uint64_t tag, int dimension) {
        Seeds& s = cache_[tag][cacheSlot(dimension)];
        if (s.generation != generation_ || s.dimension != dimension) {
            s.generation = generation_;
            s.dimension = dimension;
            s.shuffle = OwenSeed(static_cast<uint32_t>(key(tag, dimension) >> 32));
            s.seed[0] = OwenSeed(seed32(tag, dimension, 0));
            s.seed[1] = tag == kTagPadded1D ? OwenSeed() : OwenSeed(seed32(tag, dimension, 1));
        }
        return s;
    }

    uint64_t key(uint64_t tag, int dimension) const { return hashValues({pixelKey_, tag, uint64_t(dimension)}); }
    uint32_t seed32(uint64_t tag, int dimension, int component) const {
        return static_cast<uint32_t>(hashValues({pixelKey_, tag, uint64_t(dimension), uint64_t(component) + 17}) >> 32);
    }
    uint32_t shuffledIndex(const OwenSeed& shuffleSeed) const {
        return shuffledIndex(static_cast<uint32_t>(index_), shuffleSeed);
    }
    uint32_t shuffledIndex(uint32_t i, const OwenSeed& shuffleSeed) const {
        if ((i | mask_) <= 0xffu) { // up to 256 samples: both reversals are one byte's, from a table
            using sobol_detail::kReversedByte;
            const uint32_t scrambled = sobol_detail::scrambleReversed(uint32_t(kReversedByte[i]) << 24, shuffleSeed);
            return (i & ~mask_) | (kReversedByte[scrambled >> 24] & mask_);
        }
        return (i & ~mask_) | (owenScramble(i, shuffleSeed) & mask_);
    }
    const OwenSeed& jointSeed(int dimension) {
        if (!((jointSeedsReady_ >> dimension) & 1u)) {
            jointSeeds_[dimension] = OwenSeed(seed32(kTagJoint, dimension, 0));
            jointSeedsReady_ |= 1u << dimension;
        }
        return jointSeeds_[dimension];
    }
    double joint(int dimension) {
        if (dimension == 0) return fractionToUnit(scrambledSobol0(jointIndex_, jointSeeds_[0]));
        return fractionToUnit(owenScrambledSobol(jointIndex_, dimension, jointSeed(dimension)));
    }
    static Vec2 padded2D(uint32_t i, const Seeds& s) {
        return {fractionToUnit(scrambledSobol0(i, s.seed[0])),
                fractionToUnit(owenScrambledSobol(i, 1, s.seed[1]))};
    }

    // The joint (shuffled) index of the pixel's recent sample indices.
    struct Recent {
        int index = -1;
        uint32_t jointIndex = 0;
    };
    static constexpr int kRecent = 8;
    // The smallest packet whose camera values are worked out sixteen at a
    // time (spheres at 1 spp: one by one is about 9% faster per ray).
    static constexpr int kLanesFrom = 3;
    Recent recent_[kRecent];
    bool havePixel_ = false;
    uint64_t generation_ = 0;
    OwenSeed jointShuffle_;
    OwenSeed jointSeeds_[kSobolDimensions];
    uint32_t jointSeedsReady_ = 0; // bit d: jointSeeds_[d] is this pixel's
    Seeds cache_[kTags][kCacheSlots];
    uint32_t mask_ = 0;
    uint64_t pixelKey_ = 0;
    uint32_t jointIndex_ = 0;
    bool lanes_ = true;
    // The camera values of the last sixteen samples cameraLanes worked out.
    struct Ahead {
        uint64_t generation = 0; // the pixel they are for (generation_ starts at 1)
        int first = 0;           // the first sample's index
        unsigned dimensions = 0; // bit d: values[d] holds dimension d
        uint32_t joint[sobol_detail::kLanes];
        uint32_t values[kSobolDimensions][sobol_detail::kLanes];
    } ahead_;
};

} // namespace

std::unique_ptr<Sampler> makeSobolSampler(int samplesPerPixel, uint64_t seed, bool lanes) {
    return std::make_unique<SobolSampler>(samplesPerPixel, seed, lanes);
}

} // namespace drt
