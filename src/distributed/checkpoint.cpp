#include "distributed/checkpoint.h"

#include "core/temporary_files.h"

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace fs = std::filesystem;

namespace drt {

namespace {

constexpr char kMagic[] = "drt checkpoint\n";
constexpr uint32_t kFormat = 2; // 2: the scene hash is a SHA-1 (hex) of the scene text and its includes
// The byte layout of the pixel states: a checkpoint is only read by a build
// with the same one (in practice the same drt version on the same kind of machine).
constexpr uint32_t kLayout = uint32_t(sizeof(AdaptivePixel) << 16 | sizeof(TileCounts) << 8 | sizeof(void*));
constexpr uint32_t kEndianProbe = 0x01020304;

void appendString(std::vector<std::byte>& out, const std::string& s) {
    const uint32_t size = uint32_t(s.size());
    const auto* p = reinterpret_cast<const std::byte*>(&size);
    out.insert(out.end(), p, p + sizeof size);
    const auto* text = reinterpret_cast<const std::byte*>(s.data());
    out.insert(out.end(), text, text + s.size());
}

template <class T> void appendValue(std::vector<std::byte>& out, T value) {
    const auto* p = reinterpret_cast<const std::byte*>(&value);
    out.insert(out.end(), p, p + sizeof value);
}

class Reader {
public:
    explicit Reader(const std::vector<std::byte>& bytes) : bytes_(bytes) {}
    bool read(void* to, size_t size) {
        if (size > bytes_.size() - offset_) return false;
        std::memcpy(to, bytes_.data() + offset_, size);
        offset_ += size;
        return true;
    }
    template <class T> bool value(T& v) { return read(&v, sizeof v); }
    bool string(std::string& s) {
        uint32_t size = 0;
        if (!value(size) || size > bytes_.size() - offset_) return false;
        s.assign(reinterpret_cast<const char*>(bytes_.data() + offset_), size);
        offset_ += size;
        return true;
    }
    std::vector<std::byte> rest() const {
        return {bytes_.begin() + std::ptrdiff_t(offset_), bytes_.end()};
    }

private:
    const std::vector<std::byte>& bytes_;
    size_t offset_ = 0;
};

} // namespace

std::string checkpointPathFor(const std::string& output) { return output + ".drt-checkpoint"; }

Checkpoint makeCheckpoint(const RenderIdentity& identity, const RenderState& state) {
    Checkpoint checkpoint;
    checkpoint.identity = identity;
    checkpoint.crop = state.options().crop ? formatWindow(*state.options().crop) : "";
    checkpoint.tileSize = state.options().tileSize;
    state.save(checkpoint.state);
    return checkpoint;
}

std::string writeCheckpoint(const std::string& path, const Checkpoint& checkpoint) {
    const RenderIdentity& identity = checkpoint.identity;
    std::vector<std::byte> bytes;
    const auto* magic = reinterpret_cast<const std::byte*>(kMagic);
    bytes.insert(bytes.end(), magic, magic + sizeof kMagic - 1);
    appendValue(bytes, kFormat);
    appendValue(bytes, kLayout);
    appendValue(bytes, kEndianProbe);
    appendString(bytes, identity.version);
    appendString(bytes, identity.sceneHash);
    appendString(bytes, identity.settings);
    appendString(bytes, checkpoint.crop);
    appendValue(bytes, int32_t(checkpoint.tileSize));
    bytes.insert(bytes.end(), checkpoint.state.begin(), checkpoint.state.end());

    const fs::path target(path);
    const fs::path temporary =
        target.parent_path() / fmt::format(".{}.tmp-{}", target.filename().string(), ::getpid());
    const TemporaryFile removedOnSignal(temporary.string());
    FILE* file = std::fopen(temporary.c_str(), "wb");
    if (!file) return fmt::format("cannot write checkpoint '{}': {}", path, std::strerror(errno));
    const bool written = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size() &&
                         std::fflush(file) == 0 && ::fsync(fileno(file)) == 0;
    const int error = errno;
    if (std::fclose(file) != 0 || !written) {
        std::error_code ec;
        fs::remove(temporary, ec);
        return fmt::format("cannot write checkpoint '{}': {}", path, std::strerror(error ? error : EIO));
    }
    std::error_code ec;
    fs::rename(temporary, target, ec);
    if (ec) {
        fs::remove(temporary, ec);
        return fmt::format("cannot write checkpoint '{}': {}", path, ec.message());
    }
    return "";
}

std::string readCheckpoint(const std::string& path, Checkpoint& checkpoint) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec))
        return fmt::format("no checkpoint '{}' to resume from", path);
    std::ifstream in(path, std::ios::binary);
    std::vector<std::byte> bytes;
    {
        std::vector<char> chars((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        bytes.resize(chars.size());
        std::memcpy(bytes.data(), chars.data(), chars.size());
    }
    if (!in.good() && !in.eof()) return fmt::format("cannot read checkpoint '{}'", path);
    Reader reader(bytes);
    char magic[sizeof kMagic - 1];
    uint32_t format = 0, layout = 0, endian = 0;
    if (!reader.read(magic, sizeof magic) || std::memcmp(magic, kMagic, sizeof magic) != 0)
        return fmt::format("'{}' is not a drt checkpoint", path);
    if (!reader.value(format) || format != kFormat || !reader.value(layout) || !reader.value(endian))
        return fmt::format("checkpoint '{}' has another format (written by another drt version)", path);
    if (layout != kLayout || endian != kEndianProbe)
        return fmt::format("checkpoint '{}' was written by a drt built for another kind of machine", path);
    int32_t tileSize = 0;
    if (!reader.string(checkpoint.identity.version) || !reader.string(checkpoint.identity.sceneHash) ||
        !reader.string(checkpoint.identity.settings) || !reader.string(checkpoint.crop) || !reader.value(tileSize) ||
        tileSize < 1)
        return fmt::format("checkpoint '{}' is truncated", path);
    checkpoint.tileSize = tileSize;
    checkpoint.state = reader.rest();
    return "";
}

std::string checkpointMismatch(const Checkpoint& checkpoint, const std::string& path, const RenderIdentity& identity,
                               const RenderOptions& options) {
    std::string difference = describeDifference(identity, checkpoint.identity, path);
    if (!difference.empty()) return "checkpoint " + difference;
    const std::string crop = options.crop ? formatWindow(*options.crop) : "";
    if (crop != checkpoint.crop)
        return fmt::format("checkpoint '{}' is of {}, this render is of {}", path,
                           checkpoint.crop.empty() ? "the whole image" : "the crop " + checkpoint.crop,
                           crop.empty() ? "the whole image" : "the crop " + crop);
    return "";
}

} // namespace drt
