#include "instrument/jpk_reader.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <utility>

#include "instrument/zip_archive.hpp"
#include "mdr/error.hpp"

namespace mdr::instrument {

namespace {

/// value = offset + multiplier * input: JPK's `offsetmultiplier` scaling.
struct Affine {
    double offset = 0.0;
    double multiplier = 1.0;
};

/// A header as one table: its own keys, and where it holds `A.B.*=N`, the keys `A.rest` it leaves out are
/// those of `shared-data/header.properties` named `B.N.rest` (how JPK files share channel and segment
/// descriptions between curves).
class Header {
public:
    Header(const Properties& own, const Properties& shared, std::string file, std::string member)
        : own_(own), shared_(shared), file_(std::move(file)), member_(std::move(member)) {
        for (const auto& [key, value] : own_) {
            if (key.size() < 3 || key.compare(key.size() - 2, 2, ".*") != 0) continue;
            const std::string stem = key.substr(0, key.size() - 2);
            const std::size_t dot = stem.rfind('.');
            if (dot == std::string::npos) continue;
            redirects_.emplace_back(stem.substr(0, dot + 1), stem.substr(dot + 1) + "." + value + ".");
        }
    }

    const std::string* find(const std::string& key) const {
        if (const auto it = own_.find(key); it != own_.end()) return &it->second;
        for (const auto& [own_prefix, shared_prefix] : redirects_) {
            if (key.compare(0, own_prefix.size(), own_prefix) != 0) continue;
            if (const auto it = shared_.find(shared_prefix + key.substr(own_prefix.size())); it != shared_.end()) {
                return &it->second;
            }
        }
        return nullptr;
    }

    const std::string& text(const std::string& key) const {
        const std::string* value = find(key);
        if (value == nullptr) throw error(key, "(missing)", "is required");
        return *value;
    }

    double number(const std::string& key) const {
        const std::string& value = text(key);
        double result = 0.0;
        const auto [end, status] = std::from_chars(value.data(), value.data() + value.size(), result);
        if (status != std::errc() || end != value.data() + value.size()) throw error(key, value, "must be a number");
        return result;
    }

    std::size_t count(const std::string& key) const {
        const std::string& value = text(key);
        std::size_t result = 0;
        const auto [end, status] = std::from_chars(value.data(), value.data() + value.size(), result);
        if (status != std::errc() || end != value.data() + value.size()) {
            throw error(key, value, "must be a whole number >= 0");
        }
        return result;
    }

    InvalidInput error(const std::string& key, const std::string& value, const std::string& rule) const {
        return InvalidInput(file_, member_ + ": " + key + " = " + value, rule);
    }

    const std::string& file() const noexcept { return file_; }

private:
    const Properties& own_;
    const Properties& shared_;
    std::string file_;
    std::string member_;
    std::vector<std::pair<std::string, std::string>> redirects_;
};

/// How a channel's samples are stored: size and kind of one big-endian number, and the encoder's scaling.
struct Encoding {
    std::size_t bytes = 2;
    enum class Kind { signed_integer, unsigned_integer, floating } kind = Kind::signed_integer;
    Affine scaling;
};

/// The keys of a channel's description: in the segment header itself (`channel.C.data.type`,
/// `channel.C.data.encoder.*`) or, in newer files, shared (`channel.C.lcd-info.*` -> `lcd-info.N.type`, ...).
std::string data_prefix(const Header& header, const std::string& channel) {
    const std::string own = "channel." + channel + ".data.";
    return header.find(own + "type") != nullptr || header.find(own + "encoder.type") != nullptr
               ? own
               : "channel." + channel + ".";
}

Affine scaling_at(const Header& header, const std::string& prefix) {
    const std::string* style = header.find(prefix + "style");
    if (style != nullptr && *style != "offsetmultiplier") {
        throw header.error(prefix + "style", *style, "must be offsetmultiplier (the only scaling JPK files use)");
    }
    return {header.number(prefix + "offset"), header.number(prefix + "multiplier")};
}

Encoding channel_encoding(const Header& header, const std::string& channel) {
    const std::string prefix = data_prefix(header, channel);
    Encoding encoding;
    const std::string* encoder = header.find(prefix + "encoder.type");
    if (encoder == nullptr) {
        const std::string& type = header.text(prefix + "type");
        if (type == "float" || type == "float-data")
            encoding.bytes = 4;
        else if (type == "double" || type == "double-data")
            encoding.bytes = 8;
        else
            throw header.error(prefix + "type", type, "must be float-data or double-data when there is no encoder");
        encoding.kind = Encoding::Kind::floating;
        return encoding;
    }
    static const std::pair<const char*, std::pair<std::size_t, Encoding::Kind>> encoders[] = {
        {"signedshort", {2, Encoding::Kind::signed_integer}},
        {"unsignedshort", {2, Encoding::Kind::unsigned_integer}},
        {"signedinteger", {4, Encoding::Kind::signed_integer}},
        {"unsignedinteger", {4, Encoding::Kind::unsigned_integer}},
        {"signedlong", {8, Encoding::Kind::signed_integer}},
        {"unsignedlong", {8, Encoding::Kind::unsigned_integer}}};
    const auto* known = std::find_if(std::begin(encoders), std::end(encoders),
                                     [&](const auto& entry) { return *encoder == entry.first; });
    if (known == std::end(encoders)) {
        throw header.error(prefix + "encoder.type", *encoder,
                           "must be signedshort, unsignedshort, signedinteger, unsignedinteger, signedlong or "
                           "unsignedlong");
    }
    encoding.bytes = known->second.first;
    encoding.kind = known->second.second;
    encoding.scaling = scaling_at(header, prefix + "encoder.scaling.");
    return encoding;
}

/// The affine map from the encoded value to calibration slot `slot`, following each conversion's
/// `base-calibration-slot` down to the set's base.
Affine slot_affine(const Header& header, const std::string& channel, const std::string& slot) {
    const std::string set = "channel." + channel + ".conversion-set.";
    const std::string& base = header.text(set + "conversions.base");
    Affine total;
    std::string current = slot;
    std::vector<Affine> steps;
    while (current != base) {
        if (steps.size() > 16) throw header.error(set + "conversion." + slot, current, "conversion chain loops");
        const std::string conversion = set + "conversion." + current + ".";
        const std::string* defined = header.find(conversion + "defined");
        if (defined != nullptr && *defined != "true")
            throw header.error(conversion + "defined", *defined, "must be true");
        steps.push_back(scaling_at(header, conversion + "scaling."));
        current = header.text(conversion + "base-calibration-slot");
    }
    for (auto it = steps.rbegin(); it != steps.rend(); ++it) {
        total = {it->offset + it->multiplier * total.offset, it->multiplier * total.multiplier};
    }
    return total;
}

std::uint16_t from_big_endian(std::uint16_t word) {
    return std::endian::native == std::endian::little ? __builtin_bswap16(word) : word;
}
std::uint32_t from_big_endian(std::uint32_t word) {
    return std::endian::native == std::endian::little ? __builtin_bswap32(word) : word;
}
std::uint64_t from_big_endian(std::uint64_t word) {
    return std::endian::native == std::endian::little ? __builtin_bswap64(word) : word;
}

/// The big-endian numbers of type `Value` (stored as `Word`) in `bytes`, as doubles.
template <typename Word, typename Value>
void decode_as(const std::string& bytes, std::vector<double>& raw) {
    static_assert(sizeof(Word) == sizeof(Value));
    raw.resize(bytes.size() / sizeof(Word));
    for (std::size_t i = 0; i < raw.size(); ++i) {
        Word word;
        std::memcpy(&word, bytes.data() + i * sizeof(Word), sizeof word);
        word = from_big_endian(word);
        Value value;
        std::memcpy(&value, &word, sizeof value);
        raw[i] = static_cast<double>(value);
    }
}

/// The stored numbers of a channel, before the encoder's scaling.
void decode(const std::string& bytes, const Encoding& encoding, std::vector<double>& raw) {
    using Kind = Encoding::Kind;
    switch (encoding.bytes * 4 + static_cast<std::size_t>(encoding.kind)) {
        case 2 * 4 + static_cast<std::size_t>(Kind::signed_integer):
            decode_as<std::uint16_t, std::int16_t>(bytes, raw);
            break;
        case 2 * 4 + static_cast<std::size_t>(Kind::unsigned_integer):
            decode_as<std::uint16_t, std::uint16_t>(bytes, raw);
            break;
        case 4 * 4 + static_cast<std::size_t>(Kind::signed_integer):
            decode_as<std::uint32_t, std::int32_t>(bytes, raw);
            break;
        case 4 * 4 + static_cast<std::size_t>(Kind::unsigned_integer):
            decode_as<std::uint32_t, std::uint32_t>(bytes, raw);
            break;
        case 4 * 4 + static_cast<std::size_t>(Kind::floating): decode_as<std::uint32_t, float>(bytes, raw); break;
        case 8 * 4 + static_cast<std::size_t>(Kind::signed_integer):
            decode_as<std::uint64_t, std::int64_t>(bytes, raw);
            break;
        case 8 * 4 + static_cast<std::size_t>(Kind::unsigned_integer):
            decode_as<std::uint64_t, std::uint64_t>(bytes, raw);
            break;
        default: decode_as<std::uint64_t, double>(bytes, raw);
    }
}

/// The measured height sensors, preferred in this order over the piezo's `height`.
constexpr const char* measured_height_channels[] = {"capacitiveSensorHeight", "measuredHeight", "strainGaugeHeight"};

bool lists(const std::string& list, const std::string& name) {
    std::size_t at = 0;
    while (at <= list.size()) {
        const std::size_t end = std::min(list.find(' ', at), list.size());
        if (list.compare(at, end - at, name) == 0) return true;
        at = end + 1;
    }
    return false;
}

/// Where a curve's channels are read into, kept from one channel to the next.
struct ChannelScratch {
    std::string bytes;        ///< the member's inflated bytes
    std::vector<double> raw;  ///< its stored numbers
};

/// A channel of a segment: its stored numbers (`scratch.raw`) and the encoder's scaling to its base slot.
Affine read_channel(ZipArchive& zip, const Header& header, const std::string& folder, const std::string& channel,
                    std::size_t points, ChannelScratch& scratch) {
    const Encoding encoding = channel_encoding(header, channel);
    const std::string member = folder + header.text("channel." + channel + ".data.file.name");
    std::string& bytes = scratch.bytes;
    zip.read(member, bytes);
    if (bytes.size() % encoding.bytes != 0 || bytes.size() / encoding.bytes != points) {
        throw InvalidInput(zip.file(), member,
                           "holds " + std::to_string(bytes.size()) + " bytes, the segment header states " +
                               std::to_string(points) + " points of " + std::to_string(encoding.bytes) +
                               " bytes (truncated or corrupted)");
    }
    decode(bytes, encoding, scratch.raw);
    return encoding.scaling;
}

/// Appends `slot(encoder(raw))` to `out`: a channel calibrated to one slot of its conversion chain.
void append_calibrated(std::vector<double>& out, const std::vector<double>& raw, const Affine& encoder,
                       const Affine& slot) {
    const Affine total{slot.offset + slot.multiplier * encoder.offset, slot.multiplier * encoder.multiplier};
    const std::size_t start = out.size();
    out.resize(start + raw.size());
    for (std::size_t i = 0; i < raw.size(); ++i) out[start + i] = total.offset + total.multiplier * raw[i];
}

/// One curve: the segments under `root` (`""` or `index/N/`), described by `series` (its header.properties).
Curve read_series(ZipArchive& zip, const std::string& root, const Properties& series, const Properties& shared) {
    const Header series_header(series, shared, zip.file(), root + "header.properties");
    const std::string type = series_header.text("type");
    Curve curve;
    curve.source = zip.file() + (root.empty() ? "" : " " + root);
    // The segments present, in order. The header's force-segments.count is what was planned: an instrument that
    // stops early (spot3-0192 plans 3, records 2) writes fewer, and a segment past a gap is not read.
    std::size_t segments = 0;
    while (zip.contains(root + "segments/" + std::to_string(segments) + "/segment-header.properties")) ++segments;
    if (segments == 0)
        throw series_header.error(type + ".force-segments.count", "(no segments/0/)", "a curve needs a segment");
    double start_time = 0.0;
    ChannelScratch scratch;
    for (std::size_t index = 0; index < segments; ++index) {
        const std::string folder = root + "segments/" + std::to_string(index) + "/";
        const std::string member = folder + "segment-header.properties";
        const Properties own = parse_properties(zip.read(member), zip.file() + " " + member);
        const Header header(own, shared, zip.file(), member);
        const std::string& style = header.text("force-segment-header.settings.style");
        if (style != "extend" && style != "retract" && style != "pause") {
            throw header.error("force-segment-header.settings.style", style, "must be extend, retract or pause");
        }
        const std::size_t points = header.count("force-segment-header.num-points");
        const double duration = header.number("force-segment-header.duration");
        if (!(duration >= 0.0) || !std::isfinite(duration)) {
            throw header.error("force-segment-header.duration", format_value(duration), "must be finite and >= 0");
        }
        curve.segment_names.push_back(style);
        if (points == 0) {
            start_time += duration;
            continue;
        }
        const std::string& channels = header.text("channels.list");
        if (!lists(channels, "vDeflection")) throw header.error("channels.list", channels, "must list vDeflection");
        std::string height = "height";
        for (const char* measured : measured_height_channels) {
            if (lists(channels, measured)) {
                height = measured;
                break;
            }
        }
        if (!lists(channels, height)) throw header.error("channels.list", channels, "must list a height channel");
        if (curve.height_channel.empty()) curve.height_channel = height;
        if (curve.height_channel != height) {
            throw header.error("channels.list", channels,
                               "must hold the height channel of the first segment, " + curve.height_channel);
        }
        // vDeflection: volts -> distance (x sensitivity, m/V) -> force (x spring constant, N/m).
        const std::string deflection_set = "channel.vDeflection.conversion-set.conversion.";
        if (header.text(deflection_set + "force.base-calibration-slot") != "distance") {
            throw header.error(deflection_set + "force.base-calibration-slot",
                               header.text(deflection_set + "force.base-calibration-slot"), "must be distance");
        }
        const double spring_constant = header.number(deflection_set + "force.scaling.multiplier");
        const double sensitivity = header.number(deflection_set + "distance.scaling.multiplier");
        if (index == 0 || curve.spring_constant == 0.0) {
            curve.spring_constant = spring_constant;
            curve.sensitivity = sensitivity;
        }
        const std::vector<double>& raw = scratch.raw;
        const Affine volts = read_channel(zip, header, folder, "vDeflection", points, scratch);
        append_calibrated(curve.force, raw, volts, slot_affine(header, "vDeflection", "force"));
        append_calibrated(curve.deflection, raw, volts, slot_affine(header, "vDeflection", "distance"));
        const std::string& height_slot = header.text("channel." + height + ".conversion-set.conversions.default");
        const Affine height_encoder = read_channel(zip, header, folder, height, points, scratch);
        append_calibrated(curve.height, raw, height_encoder, slot_affine(header, height, height_slot));
        const double step = duration / static_cast<double>(points);
        if (curve.segment_names.size() > std::numeric_limits<std::uint16_t>::max()) {
            throw header.error("force-segment-header", member, "a curve holds at most 65535 segments");
        }
        const auto segment = static_cast<std::uint16_t>(curve.segment_names.size() - 1);
        const std::size_t first = curve.time.size();
        curve.time.resize(first + points);
        for (std::size_t i = 0; i < points; ++i) curve.time[first + i] = start_time + static_cast<double>(i) * step;
        curve.segment.insert(curve.segment.end(), points, segment);
        start_time += duration;
    }
    if (curve.force.empty()) throw series_header.error(type, "(no samples)", "a curve needs samples");
    if (!(curve.spring_constant > 0.0)) {
        throw series_header.error("spring constant", format_value(curve.spring_constant), "must be > 0");
    }
    return curve;
}

/// `N` of a member `index/N/header.properties`, or false.
bool map_index(const std::string& name, std::size_t& index) {
    constexpr std::string_view head = "index/";
    constexpr std::string_view tail = "/header.properties";
    if (name.size() <= head.size() + tail.size() || name.compare(0, head.size(), head) != 0 ||
        name.compare(name.size() - tail.size(), tail.size(), tail) != 0) {
        return false;
    }
    const char* first = name.data() + head.size();
    const char* last = name.data() + name.size() - tail.size();
    const auto [end, status] = std::from_chars(first, last, index);
    return status == std::errc() && end == last;
}

/// The pixel of a position on the grid, from the grid's centre, edge lengths and rotation `theta` (rad).
void place_on_grid(const Header& map, const std::string& type, Curve& curve) {
    const std::string grid = type + ".position-pattern.grid.";
    MapGrid& g = curve.grid;
    g.columns = map.count(grid + "ilength");
    g.rows = map.count(grid + "jlength");
    g.size_x = map.number(grid + "ulength");
    g.size_y = map.number(grid + "vlength");
    g.center_x = map.number(grid + "xcenter");
    g.center_y = map.number(grid + "ycenter");
    const double theta = map.find(grid + "theta") != nullptr ? map.number(grid + "theta") : 0.0;
    if (g.columns == 0 || g.rows == 0 || !(g.size_x > 0.0) || !(g.size_y > 0.0)) {
        throw map.error(grid + "ilength", std::to_string(g.columns) + " x " + std::to_string(g.rows),
                        "the grid needs pixels and edge lengths > 0");
    }
    const double dx = curve.position.x - g.center_x;
    const double dy = curve.position.y - g.center_y;
    const double u = std::cos(theta) * dx + std::sin(theta) * dy + 0.5 * g.size_x;
    const double v = -std::sin(theta) * dx + std::cos(theta) * dy + 0.5 * g.size_y;
    const double column = std::floor(u / g.size_x * static_cast<double>(g.columns));
    const double row = std::floor(v / g.size_y * static_cast<double>(g.rows));
    if (!(column >= 0.0 && column < static_cast<double>(g.columns) && row >= 0.0 &&
          row < static_cast<double>(g.rows))) {
        throw InvalidInput(map.file(), curve.source,
                           "position (" + format_value(curve.position.x) + ", " + format_value(curve.position.y) +
                               ") m lies outside the map's grid");
    }
    curve.position.column = static_cast<std::size_t>(column);
    curve.position.row = static_cast<std::size_t>(row);
}

bool ends_with(const std::string& text, std::string_view tail) {
    return text.size() >= tail.size() && text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

JpkSource::JpkSource(const std::filesystem::path& path, const ReadOptions& options)
    : zip_(std::make_unique<ZipArchive>(path)) {
    refuse_calibration(options, zip_->file());
    ZipArchive& zip = *zip_;
    top_ = parse_properties(zip.read("header.properties"), zip.file() + " header.properties");
    if (zip.contains("shared-data/header.properties")) {
        shared_ =
            parse_properties(zip.read("shared-data/header.properties"), zip.file() + " shared-data/header.properties");
    }
    const Header header(top_, shared_, zip.file(), "header.properties");
    type_ = header.text("type");
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    const bool map = ends_with(type_, "-map");
    if (!map && !ends_with(type_, "-series")) {
        throw header.error("type", type_, "must be a force-scan series or map (a JPK force file)");
    }
    if ((extension == ".jpk-force" && map) ||
        ((extension == ".jpk-force-map" || extension == ".jpk-qi-data") && !map)) {
        throw header.error("type", type_, "does not match the file name's ending " + extension);
    }
    if (!map) {
        roots_.emplace_back();
        return;
    }
    top_metadata_.insert(top_.begin(), top_.end());
    std::vector<std::size_t> indices;
    for (const std::string& name : zip.names()) {
        std::size_t index = 0;
        if (map_index(name, index)) indices.push_back(index);
    }
    std::sort(indices.begin(), indices.end());
    if (indices.empty()) throw header.error(type_, "(no index/N/header.properties)", "a map needs curves");
    const std::size_t lowest = header.count(type_ + ".indexes.min");
    const std::size_t highest = header.count(type_ + ".indexes.max");
    for (const std::size_t index : indices) {
        if (index < lowest || index > highest) {
            throw header.error(type_ + ".indexes.max", std::to_string(highest),
                               "the archive holds curve index/" + std::to_string(index) + " outside " +
                                   std::to_string(lowest) + ".." + std::to_string(highest));
        }
        roots_.push_back("index/" + std::to_string(index) + "/");
        if (!zip.contains(roots_.back() + "segments/0/segment-header.properties")) {
            throw InvalidInput(zip.file(), roots_.back(), "a curve of the map has no segments/0/ (missing pixel data)");
        }
    }
}

JpkSource::~JpkSource() = default;

std::size_t JpkSource::size() const {
    return roots_.size();
}

Curve JpkSource::read(std::size_t index) {
    ZipArchive& zip = *zip_;
    const std::string& root = roots_.at(index);
    if (root.empty()) {
        Curve curve = read_series(zip, "", top_, shared_);
        curve.metadata.insert(top_.begin(), top_.end());
        return curve;
    }
    const Properties series =
        parse_properties(zip.read(root + "header.properties"), zip.file() + " " + root + "header.properties");
    Curve curve = read_series(zip, root, series, shared_);
    const Header series_header(series, shared_, zip.file(), root + "header.properties");
    const std::string series_type = series_header.text("type");
    curve.in_map = true;
    curve.position.x = series_header.number(series_type + ".header.position.x");
    curve.position.y = series_header.number(series_type + ".header.position.y");
    curve.position.index = series_header.count(series_type + ".header.position-index");
    place_on_grid(Header(top_, shared_, zip.file(), "header.properties"), type_, curve);
    // The map's header, copied whole (a tree copy makes no comparisons), then the curve's own, which wins.
    curve.metadata = top_metadata_;
    for (const auto& [key, value] : series) curve.metadata.insert_or_assign(key, value);
    return curve;
}

}  // namespace mdr::instrument
