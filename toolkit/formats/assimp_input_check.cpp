#include "toolkit/formats/assimp_input_check.h"

#include "toolkit/formats/step_file_check.h"

#include "base/graph_check.h"
#include "base/input_error.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <limits>
#include <optional>
#include <sstream>
#include <unordered_map>
#include <vector>

namespace boxlod {
namespace {

[[noreturn]] void refuse_count(const std::string& file, const std::string& place, std::size_t count,
                               std::size_t bytes) {
    throw_input_error(file, place,
                      "claims " + std::to_string(count) + " entries, more than the file's " +
                          std::to_string(bytes) + " bytes can hold");
}

// `count` entries of at least `entry_bytes` each within `available` bytes, without overflow.
void check_fits(std::size_t count, std::size_t entry_bytes, std::size_t& available, const std::string& file,
                const std::string& place) {
    std::size_t needed = 0;
    if (!checked_multiply(count, entry_bytes, needed) || needed > available)
        refuse_count(file, place, count, available);
    available -= needed;
}

std::size_t parse_count(const std::string& word, const std::string& file, const std::string& place) {
    std::size_t value = 0;
    auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (error != std::errc() || end != word.data() + word.size())
        throw_input_error(file, place, "expected a count, got '" + word + "'");
    return value;
}

// PLY (Turk 1994): `element NAME COUNT` lines, each followed by its properties.
// An ASCII entry needs at least two bytes per property ("0 "); a binary one the
// size of its scalar properties and of each list's count. assimp 5.2 loops for
// ever on a header without its end, and takes seconds per thousand elements.
constexpr int max_ply_elements = 1000;

struct PlyElement {
    std::string name;
    std::size_t count = 0, entry_bytes = 0;
    int line = 0;
    std::vector<bool> lists;  // each property: a list (a count, then that many numbers) or one number
};

// assimp reads an ASCII body on across lines: a list longer than its line, or a body cut short, took the
// next entries' numbers (a face "200 0 1 2" became 199 triangles). Writers put each entry on a line of
// its own: each line must hold its entry whole, no more and no less. `number` is the body's first line.
void check_ascii_ply_body(std::string_view data, int number, const std::vector<PlyElement>& elements,
                          const std::string& file) {
    for (const PlyElement& element : elements)
        for (std::size_t entry = 0; entry < element.count; ++entry) {
            std::vector<std::string_view> words;
            for (; words.empty(); ++number) {  // the entry's line: the next that holds anything
                if (data.empty())
                    throw_input_error(file, "line " + std::to_string(number),
                                      "the file ends at element '" + element.name + "' entry " +
                                          std::to_string(entry) + " of " + std::to_string(element.count) +
                                          " (truncated file?)");
                const std::string_view line = data.substr(0, std::min(data.find('\n'), data.size()));
                data.remove_prefix(std::min(line.size() + 1, data.size()));
                for (std::size_t i = line.find_first_not_of(" \t\r"); i != std::string_view::npos;
                     i = line.find_first_not_of(" \t\r", i)) {
                    const std::size_t end = std::min(line.find_first_of(" \t\r", i), line.size());
                    words.push_back(line.substr(i, end - i));
                    i = end;
                }
            }
            std::size_t taken = 0;  // the numbers its properties take
            for (bool list : element.lists) {
                std::size_t length = 0;
                if (list && taken < words.size())
                    std::from_chars(words[taken].data(), words[taken].data() + words[taken].size(), length);
                taken += 1 + std::min<std::size_t>(length, std::size_t(1) << 40);
            }
            if (taken != words.size())
                throw_input_error(file, "line " + std::to_string(number - 1),
                                  "element '" + element.name + "' entry " + std::to_string(entry) + ": " +
                                      std::to_string(words.size()) + " numbers where its properties take " +
                                      std::to_string(taken));
        }
}

void check_ply(std::string_view bytes, const std::string& file) {
    std::size_t header_end = bytes.find("end_header");
    if (header_end == std::string_view::npos)
        throw_input_error(file, "", "the header has no 'end_header' line (truncated file?)");
    std::istringstream header{std::string(bytes.substr(0, header_end))};
    std::size_t body = bytes.size() - std::min(bytes.size(), header_end + 11);
    bool ascii = true;
    std::vector<PlyElement> elements;
    auto type_bytes = [](const std::string& type) -> std::size_t {
        if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
        if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
        if (type == "double" || type == "float64") return 8;
        return 4;
    };
    std::string line;
    int number = 1;
    for (; std::getline(header, line); ++number) {
        std::istringstream words(line);
        std::string keyword, a, b, c;
        words >> keyword >> a >> b >> c;
        std::string place = "line " + std::to_string(number);
        if (keyword == "format") ascii = a == "ascii";
        if (keyword == "element") elements.push_back({a, parse_count(b, file, place), 0, number, {}});
        if (elements.size() > max_ply_elements)
            throw_input_error(file, place, "more than " + std::to_string(max_ply_elements) + " elements");
        if (keyword == "property" && !elements.empty()) {
            elements.back().entry_bytes += ascii ? 2 : a == "list" ? type_bytes(b) : type_bytes(a);
            elements.back().lists.push_back(a == "list");
        }
    }
    for (const PlyElement& element : elements)
        check_fits(element.count, std::max<std::size_t>(element.entry_bytes, 1), body, file,
                   "line " + std::to_string(element.line) + ": element '" + element.name + "'");
    // The body starts on the line after end_header's.
    std::string_view data = bytes.substr(std::min(bytes.size(), header_end));
    data.remove_prefix(std::min(data.find('\n'), data.size() - 1) + 1);
    const bool own_line = header_end > 0 && bytes[header_end - 1] == '\n';  // `number` is end_header's line
    if (ascii) check_ascii_ply_body(data, number + (own_line ? 1 : 0), elements, file);
}

// An OBJ's lines as words, '#' comments left out and lines ending in '\\' joined with the next; `visit`
// gets each line's number and words.
void for_each_obj_line(std::string_view bytes,
                       const std::function<void(int, const std::vector<std::string_view>&)>& visit) {
    std::vector<std::string_view> words;
    int number = 0, first = 1;
    for (std::size_t start = 0; start < bytes.size();) {
        // A line ends at LF, CR LF or a lone CR (old Mac OS exporters), as assimp reads it.
        const std::size_t end = std::min(bytes.find_first_of("\r\n", start), bytes.size());
        std::string_view line = bytes.substr(start, end - start);
        start = end + (bytes.substr(end, 2) == "\r\n" ? 2 : 1);
        ++number;
        line = line.substr(0, std::min(line.find('#'), line.size()));
        while (!line.empty() && (line.back() == ' ' || line.back() == '\t')) line.remove_suffix(1);
        const bool continued = !line.empty() && line.back() == '\\';
        if (continued) line.remove_suffix(1);
        for (std::size_t i = 0; i < line.size();) {
            const std::size_t word = line.find_first_not_of(" \t", i);
            if (word == std::string_view::npos) break;
            i = std::min(line.find_first_of(" \t", word), line.size());
            words.push_back(line.substr(word, i - word));
        }
        if (continued) continue;
        if (!words.empty()) visit(first, words);
        words.clear();
        first = number + 1;
    }
    if (!words.empty()) visit(first, words);
}

// OBJ's `mtllib NAME` (the rest of the line, beside the file): assimp opens it itself, or where it is
// missing the OBJ's own name with .mtl, so a FIFO there would block it for ever and a folder read as "File
// read error"; a library it does not find it skips silently, drawing its materials grey.
void check_obj_material_libraries(std::string_view bytes, const std::string& file) {
    for_each_obj_line(bytes, [&](int number, const std::vector<std::string_view>& words) {
        if (words[0] != "mtllib" || words.size() < 2) return;
        const std::string name(words[1].data(), words.back().data() + words.back().size());
        const std::string place = "line " + std::to_string(number);
        const std::filesystem::path folder = std::filesystem::path(file).parent_path();
        std::filesystem::path library = folder / name;
        std::error_code error;
        if (std::filesystem::status(library, error).type() == std::filesystem::file_type::not_found)
            library = folder / (std::filesystem::path(file).stem().string() + ".mtl");
        const std::filesystem::file_type type = std::filesystem::status(library, error).type();
        if (type == std::filesystem::file_type::not_found)
            std::fprintf(
                stderr, "boxlod: warning: %s\n",
                input_message(file, place, "mtllib '" + name + "' is missing: its materials are drawn grey")
                    .c_str());
        else if (type != std::filesystem::file_type::regular)
            throw_input_error(file, place,
                              "mtllib '" + library.filename().string() +
                                  "' is not a regular file (a folder, FIFO or device)");
    });
}

// OBJ (Wavefront): `v` and `vt` numbers finite in float (assimp reads "nan", "1e39" or "0x10" as 0
// without a word; a `vn` of NaN, which tools write for degenerate faces, reads as 0 and boxlod makes the
// part's normals anew), faces of 3 or more corners ("v", "v/t", "v//n", "v/t/n"), and every index naming one
// of the file's (1-based; negative: counted back from the latest so far): assimp drops an out-of-range
// texture coordinate or normal index silently, and with it the material's texture.
void check_obj(std::string_view bytes, const std::string& file) {
    const std::array<std::string_view, 3> kinds{"v", "vt", "vn"};
    const std::array<const char*, 3> names{"vertex", "texture coordinate", "normal"};
    const std::array<const char*, 3> plurals{"vertices", "texture coordinates", "normals"};
    std::array<long long, 3> total{}, so_far{};
    for_each_obj_line(bytes, [&](int, const std::vector<std::string_view>& words) {
        for (std::size_t k = 0; k < kinds.size(); ++k) total[k] += words[0] == kinds[k];
    });
    for_each_obj_line(bytes, [&](int number, const std::vector<std::string_view>& words) {
        const std::string place = "line " + std::to_string(number);
        for (std::size_t k = 0; k < kinds.size(); ++k) {
            if (words[0] != kinds[k]) continue;
            ++so_far[k];
            for (std::size_t w = 1; w < words.size() && words[0] != "vn"; ++w) {
                double value = 0;
                std::string_view number = words[w];
                if (number.size() > 1 && number[0] == '+' && number[1] != '-')
                    number.remove_prefix(1);  // "+2."
                auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
                if (error != std::errc() || end != number.data() + number.size() ||
                    !(std::abs(value) <= std::numeric_limits<float>::max()))
                    throw_input_error(file, place, "'" + std::string(words[w]) + "' is not a finite number");
            }
        }
        if (words[0] != "f" && words[0] != "l" && words[0] != "p") return;
        if (words[0] == "f" && words.size() < 4)
            throw_input_error(file, place, "a face of fewer than 3 corners");
        for (std::size_t w = 1; w < words.size(); ++w) {
            std::string_view rest = words[w];
            for (std::size_t k = 0; k < kinds.size() && !rest.empty(); ++k) {
                const std::string_view index_text = rest.substr(0, std::min(rest.find('/'), rest.size()));
                rest.remove_prefix(std::min(index_text.size() + 1, rest.size()));
                if (index_text.empty() && k > 0) continue;  // "v//n"
                long long index = 0;
                auto [end, error] =
                    std::from_chars(index_text.data(), index_text.data() + index_text.size(), index);
                const bool names_one = index > 0 ? index <= total[k] : index < 0 && -index <= so_far[k];
                if (error != std::errc() || end != index_text.data() + index_text.size() || !names_one)
                    throw_input_error(file, place,
                                      "corner '" + std::string(words[w]) + "': " + names[k] + " index '" +
                                          std::string(index_text) + "' is not one of the " +
                                          std::to_string(index < 0 ? so_far[k] : total[k]) + " " +
                                          plurals[k] + (index < 0 ? " before it" : " in the file"));
            }
            if (!rest.empty())
                throw_input_error(file, place,
                                  "corner '" + std::string(words[w]) + "' has more than 3 indices");
        }
    });
}

// An OFF face "n i1 .. in": n whole indices, each naming one of the file's vertices.
void check_off_face(const std::string& line, std::size_t vertices, const std::string& file,
                    const std::string& at) {
    std::istringstream face(line);
    std::string corners_text, index_text;
    face >> corners_text;
    const std::size_t corners = parse_count(corners_text, file, at);
    for (std::size_t k = 0; k < corners; ++k) {
        long long index = -1;  // signed: a "-1" is reported as itself, not wrapped around
        if (!(face >> index_text))
            throw_input_error(file, at,
                              "a face of " + std::to_string(corners) + " corners gives " + std::to_string(k) +
                                  " vertex indices");
        auto [end, error] = std::from_chars(index_text.data(), index_text.data() + index_text.size(), index);
        if (error != std::errc() || end != index_text.data() + index_text.size() || index < 0 ||
            std::size_t(index) >= vertices)
            throw_input_error(file, at,
                              "vertex index " + index_text + " is not one of the " +
                                  std::to_string(vertices) + " vertices (0 to " + std::to_string(vertices) +
                                  " - 1)");
    }
}

// OFF (Geomview): "OFF", vertex, face and edge counts, a line per vertex, a
// line per face "n i1 .. in". A vertex needs at least "0 0 0\n" (6 bytes), a
// face "0\n" (2 bytes); every index must name a vertex (assimp would clamp it).
void check_off(std::string_view bytes, const std::string& file) {
    std::istringstream in{std::string(bytes)};
    std::string line;
    int number = 0;
    auto next_line = [&]() {
        while (std::getline(in, line)) {
            ++number;
            std::size_t start = line.find_first_not_of(" \t\r");
            if (start != std::string::npos && line[start] != '#') return true;
        }
        return false;
    };
    if (!next_line() || line.find("OFF") == std::string::npos || line.find("BINARY") != std::string::npos)
        return;
    // The counts follow "OFF" on its line or on the next.
    std::istringstream header(line.substr(line.find("OFF") + 3));
    std::string vertices_text, faces_text;
    if (!(header >> vertices_text)) {
        if (!next_line()) return;
        header = std::istringstream(line);
        header >> vertices_text;
    }
    if (!(header >> faces_text)) return;
    const std::string place = "line " + std::to_string(number);
    std::size_t vertices = parse_count(vertices_text, file, place),
                faces = parse_count(faces_text, file, place);
    std::size_t available = bytes.size();
    check_fits(vertices, 6, available, file, place + ": vertex count");
    check_fits(faces, 2, available, file, place + ": face count");
    // A file cut short, a face with fewer indices than its count, or an index "2.7" assimp read as 2 or
    // as a face without indices (its validation then named mIndices).
    const auto ends = [&](const char* what, std::size_t k, std::size_t of) {
        throw_input_error(file, place,
                          std::string("the file ends at ") + what + " " + std::to_string(k) + " of " +
                              std::to_string(of) + " (truncated file?)");
    };
    for (std::size_t v = 0; v < vertices; ++v)
        if (!next_line()) ends("vertex", v, vertices);
    for (std::size_t f = 0; f < faces; ++f) {
        if (!next_line()) ends("face", f, faces);
        check_off_face(line, vertices, file, "line " + std::to_string(number));
    }
}

// ASCII STL: each facet's loop holds three vertices (assimp drew a facet of four as one triangle and
// dropped the fourth without a word). A binary STL, whose 80-byte header may also start with "solid", is
// told by its size: 84 bytes and 50 a triangle.
void check_ascii_stl(std::string_view bytes, const std::string& file) {
    std::uint32_t triangles = 0;
    if (bytes.size() >= 84) std::memcpy(&triangles, bytes.data() + 80, 4);
    if (!bytes.starts_with("solid") ||
        (bytes.size() >= 84 && bytes.size() == 84 + 50 * std::size_t(triangles)))
        return;
    int line = 1, loop_line = 0, vertices = -1;  // -1: outside a loop
    for (std::size_t i = 0; i < bytes.size();) {
        const std::size_t start = bytes.find_first_not_of(" \t\r", i);
        if (start == std::string_view::npos) break;
        if (bytes[start] == '\n') {
            ++line;
            i = start + 1;
            continue;
        }
        const std::size_t end = std::min(bytes.find_first_of(" \t\r\n", start), bytes.size());
        const std::string_view word = bytes.substr(start, end - start);
        i = end;
        if (word == "loop") loop_line = line, vertices = 0;
        if (word == "vertex" && vertices >= 0) ++vertices;
        if (word == "endloop" && vertices != 3)
            throw_input_error(file, "line " + std::to_string(loop_line),
                              "a facet's loop of " + std::to_string(vertices) + " vertices (STL's hold 3)");
        if (word == "endloop") vertices = -1;
    }
}

// Calls visit(at, tag) for each tag of an XML file (`tag` its text from '<' to '>', quoted attribute values
// held whole), skipping comments, CDATA sections, processing instructions and declarations; the text
// between tags is left to the visitor.
template <typename Visit>
void for_each_xml_tag(std::string_view bytes, Visit&& visit) {
    static constexpr std::pair<std::string_view, std::string_view> skipped[] = {
        {"<!--", "-->"}, {"<![CDATA[", "]]>"}, {"<?", "?>"}};
    for (std::size_t i = bytes.find('<'); i != std::string_view::npos; i = bytes.find('<', i + 1)) {
        const auto skip = std::find_if(std::begin(skipped), std::end(skipped), [&](const auto& pair) {
            return bytes.substr(i, pair.first.size()) == pair.first;
        });
        if (skip != std::end(skipped)) {
            i = bytes.find(skip->second, i);
            if (i == std::string_view::npos) return;
            continue;
        }
        std::size_t end = i + 1;
        for (char quote = 0; end < bytes.size() && (quote || bytes[end] != '>'); ++end)
            if (bytes[end] == '"' || bytes[end] == '\'')
                quote = quote == bytes[end] ? 0 : quote ? quote : bytes[end];
        if (end >= bytes.size()) return;
        visit(i, bytes.substr(i, end + 1 - i));
        i = end;
    }
}

// XML formats (COLLADA, X3D): elements nested at most max_nesting_depth deep
// (assimp's readers recurse per element).
void check_xml_depth(std::string_view bytes, const std::string& file) {
    int depth = 0;
    for_each_xml_tag(bytes, [&](std::size_t at, std::string_view tag) {
        if (tag[1] == '/') {
            --depth;
            return;
        }
        if (tag[1] != '!' && tag[tag.size() - 2] != '/' && ++depth > max_nesting_depth)
            throw_input_error(file, "byte " + std::to_string(at), "XML elements " + nesting_message());
    });
}

// The value of attribute `name` in an XML tag (its text from '<' to '>'), if the tag has it.
std::optional<std::string_view> xml_attribute(std::string_view tag, std::string_view name) {
    const auto space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
    for (std::size_t at = tag.find(name); at != std::string_view::npos; at = tag.find(name, at + 1)) {
        std::size_t i = at + name.size();
        while (i < tag.size() && space(tag[i])) ++i;
        if (at == 0 || !space(tag[at - 1]) || i >= tag.size() || tag[i] != '=') continue;
        for (++i; i < tag.size() && space(tag[i]);) ++i;
        if (i >= tag.size() || (tag[i] != '"' && tag[i] != '\'')) continue;
        const std::size_t end = tag.find(tag[i], i + 1);
        if (end == std::string_view::npos) return std::nullopt;
        return tag.substr(i + 1, end - i - 1);
    }
    return std::nullopt;
}

// A COLLADA tag's element name without a namespace prefix ("float_array" of <c:float_array ...>).
std::string_view collada_element(std::string_view tag) {
    std::string_view name = tag.substr(1, tag.find_first_of(" \t\r\n/>", 1) - 1);
    return name.substr(name.find(':') == std::string_view::npos ? 0 : name.find(':') + 1);
}

struct ColladaAccessor {
    std::size_t at;  // its byte in the file
    std::string source;
    std::size_t offset, count, stride, params;
};

// Each accessor reads within its array: offset + (count - 1) x stride + its params values, without overflow.
void check_collada_accessors(const std::vector<ColladaAccessor>& accessors,
                             const std::unordered_map<std::string, std::size_t>& array_values,
                             const std::string& file) {
    for (const ColladaAccessor& accessor : accessors) {
        const auto array = array_values.find(accessor.source);
        std::size_t reach = 0;  // offset + (count - 1) x stride + params, without overflow
        if (array == array_values.end() || accessor.count == 0) continue;
        if (!checked_multiply(accessor.count - 1, accessor.stride, reach) ||
            !range_fits(accessor.offset, reach, array->second) ||
            !range_fits(accessor.offset + reach, accessor.params, array->second))
            throw_input_error(file, "byte " + std::to_string(accessor.at) + " <accessor>",
                              "reads past its array " + accessor.source + " of " +
                                  std::to_string(array->second) +
                                  " values (offset + (count - 1) x stride + its params)");
    }
}

// COLLADA's arrays and accessors (COLLADA 1.4.1 specification, chapter 5: float_array, accessor): an array
// holds at least the values its count says, and an accessor reads within its array: offset + (count - 1) x
// stride + its params values at most (interleaved accessors share an array). assimp reads an array by its
// count and an accessor by its own count and stride, past the values the file holds: what a short array
// read differed from run to run. Accessors are checked once every array is known (one may come first).
void check_collada_arrays(std::string_view bytes, const std::string& file) {
    static constexpr std::string_view arrays[] = {"float_array", "int_array",    "bool_array", "Name_array",
                                                  "IDREF_array", "SIDREF_array", "token_array"};
    std::unordered_map<std::string, std::size_t> array_values;  // "#id": its count, the smallest of an id's
    std::vector<ColladaAccessor> accessors;
    const auto number = [&](std::string_view tag, std::size_t at, std::string_view attribute,
                            std::size_t fallback) {
        const std::optional<std::string_view> text = xml_attribute(tag, attribute);
        return text ? parse_count(std::string(*text), file,
                                  "byte " + std::to_string(at) + " " + std::string(attribute))
                    : fallback;
    };
    for_each_xml_tag(bytes, [&](std::size_t at, std::string_view tag) {
        const std::string_view name = collada_element(tag);
        const std::size_t end = at + tag.size();
        if (std::find(std::begin(arrays), std::end(arrays), name) != std::end(arrays)) {
            const std::size_t count = number(tag, at, "count", 0);
            std::size_t values = 0;
            const std::string_view content = tag[tag.size() - 2] == '/'
                                                 ? std::string_view()
                                                 : bytes.substr(end, bytes.find('<', end) - end);
            for (std::size_t c = 0; c < content.size(); ++c)
                values += !std::isspace(static_cast<unsigned char>(content[c])) &&
                          (c == 0 || std::isspace(static_cast<unsigned char>(content[c - 1])));
            if (values < count)
                throw_input_error(
                    file, "byte " + std::to_string(at) + " <" + std::string(name) + ">",
                    "count " + std::to_string(count) + " but " + std::to_string(values) + " values");
            if (auto id = xml_attribute(tag, "id")) {
                auto [known, added] = array_values.emplace("#" + std::string(*id), count);
                known->second = std::min(known->second, count);
            }
        } else if (name == "accessor") {
            const std::size_t close = tag[tag.size() - 2] == '/' ? end : bytes.find("accessor>", end);
            const std::string_view inside =
                bytes.substr(end, close == std::string_view::npos ? 0 : close - end);
            std::size_t params = 0;
            for (std::size_t p = inside.find("param"); p != std::string_view::npos;
                 p = inside.find("param", p + 1))
                params += p > 0 && (inside[p - 1] == '<' || inside[p - 1] == ':');
            accessors.push_back({at, std::string(xml_attribute(tag, "source").value_or("")),
                                 number(tag, at, "offset", 0), number(tag, at, "count", 0),
                                 number(tag, at, "stride", 1), std::max<std::size_t>(params, 1)});
        }
    });
    check_collada_accessors(accessors, array_values, file);
}

// COLLADA's node tree with its instance_node references (COLLADA 1.4.1 specification, chapter 5: node,
// instance_node): assimp builds the scene by recursion through every node a node instances (found by its
// id, else its name, anywhere in the file), so nodes that instance each other crashed it.
void check_collada_nodes(std::string_view bytes, const std::string& file) {
    std::vector<std::vector<std::uint32_t>> edges;  // a node's children and the nodes it instances
    std::vector<std::string> places;                // "byte N <node id="a">"
    std::unordered_map<std::string_view, std::uint32_t> ids, names;
    std::vector<std::pair<std::uint32_t, std::string_view>> instances;  // (node, the id it instances)
    std::vector<std::uint32_t> open;
    for_each_xml_tag(bytes, [&](std::size_t at, std::string_view tag) {
        const bool closing = tag[1] == '/';
        const std::string_view name = collada_element(closing ? tag.substr(1) : tag);
        if (name == "node" && closing) {
            if (!open.empty()) open.pop_back();
        } else if (name == "node") {
            const auto node = std::uint32_t(edges.size());
            edges.emplace_back();
            const std::optional<std::string_view> id = xml_attribute(tag, "id");
            places.push_back("byte " + std::to_string(at) + " <node" +
                             (id ? " id=\"" + std::string(id->substr(0, 40)) + "\"" : "") + ">");
            if (!open.empty()) edges[open.back()].push_back(node);
            if (id) ids.emplace(*id, node);
            if (auto node_name = xml_attribute(tag, "name")) names.emplace(*node_name, node);
            if (tag[tag.size() - 2] != '/') open.push_back(node);
        } else if (name == "instance_node" && !open.empty()) {
            const std::string_view url = xml_attribute(tag, "url").value_or("");
            if (!url.empty() && url[0] == '#') instances.emplace_back(open.back(), url.substr(1));
        }
    });
    for (const auto& [node, id] : instances) {
        if (const auto by_id = ids.find(id); by_id != ids.end())
            edges[node].push_back(by_id->second);
        else if (const auto by_name = names.find(id); by_name != names.end())
            edges[node].push_back(by_name->second);
    }
    check_acyclic_and_shallow(
        edges, [&](std::uint32_t node) { return places[node]; }, "nodes with the nodes they instance", file,
        max_nesting_depth);
}

}  // namespace

void check_assimp_input(std::string_view bytes, const std::string& extension, const std::string& file) {
    if (extension == ".obj") {
        check_obj(bytes, file);
        check_obj_material_libraries(bytes, file);
    }
    if (extension == ".ply") check_ply(bytes, file);
    if (extension == ".off") check_off(bytes, file);
    if (extension == ".stl") check_ascii_stl(bytes, file);
    if (extension == ".dae" || extension == ".x3d") check_xml_depth(bytes, file);
    if (extension == ".dae") {
        check_collada_arrays(bytes, file);
        check_collada_nodes(bytes, file);
    }
    if (extension == ".ifc" || extension == ".stp" || extension == ".step")
        check_step_file(bytes, file, max_nesting_depth);
}

}  // namespace boxlod
