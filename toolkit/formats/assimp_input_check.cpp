#include "toolkit/formats/assimp_input_check.h"

#include "toolkit/formats/step_file_check.h"
#include "toolkit/formats/xml_file_check.h"

#include "base/input_error.h"
#include "base/number_text.h"

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
        if (keyword == "element") elements.push_back({a, read_count(b, file, place), 0, number, {}});
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
    const std::size_t corners = read_count(corners_text, file, at);
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
    std::size_t vertices = read_count(vertices_text, file, place),
                faces = read_count(faces_text, file, place);
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

[[noreturn]] void refuse_fbx_depth(const std::string& file, std::size_t at) {
    throw_input_error(file, "byte " + std::to_string(at), "FBX scopes " + nesting_message());
}

// A binary FBX's node records (Blender's io_scene_fbx, "FBX binary file format specification"): from byte
// 27, each an end offset, a property count, the properties' length (32-bit each, 64-bit from version 7500),
// a name's length (a byte) and its name, the properties, then its nested records up to its end, closed by a
// null record. Walked as assimp's FBXBinaryTokenizer walks them: a nested list ends a null record's length
// before its end, and a zero end offset inside it is skipped by its own width. Records whose offsets make no
// sense are left to assimp, which refuses them.
void check_binary_fbx_depth(std::string_view bytes, const std::string& file) {
    std::uint32_t version = 0;
    std::memcpy(&version, bytes.data() + 23, sizeof version);
    const bool wide = version >= 7500;
    const std::size_t header = wide ? 25 : 13;
    const auto field = [&](std::size_t at, int k) {
        std::uint64_t value = 0;
        std::memcpy(&value, bytes.data() + at + std::size_t(k) * (wide ? 8 : 4), wide ? 8 : 4);
        return value;  // little-endian, as the machine
    };
    std::vector<std::uint64_t> open;  // the ends of the records whose nested records are being read
    for (std::size_t at = 27; at + header <= bytes.size();) {
        if (!open.empty() && at + header >= open.back()) {  // the nested list's end
            at = std::max(at, std::size_t(open.back()));    // never back: the walk ends
            open.pop_back();
            continue;
        }
        const std::uint64_t end = field(at, 0), properties_length = field(at, 2);
        if (end == 0 && open.empty()) return;  // the top level's null record
        if (end == 0) {                        // a zero end offset inside a nested list
            at += wide ? 8 : 4;
            continue;
        }
        const std::uint64_t nested = at + header + std::uint8_t(bytes[at + header - 1]) + properties_length;
        if (end <= at || end > bytes.size() || properties_length > bytes.size()) return;
        if (nested >= end) {
            at = std::size_t(end);
            continue;
        }
        open.push_back(end);
        if (open.size() > std::size_t(max_nesting_depth)) refuse_fbx_depth(file, at);
        at = std::size_t(nested);
    }
}

// FBX (binary, or ASCII: scopes in braces, ';' comments, '"' strings): scopes nested at most
// max_nesting_depth deep (assimp's parsers recurse per scope: 200,000 crashed them).
void check_fbx_depth(std::string_view bytes, const std::string& file) {
    constexpr std::string_view binary_magic("Kaydara FBX Binary");  // the 18 bytes assimp compares
    if (bytes.substr(0, binary_magic.size()) == binary_magic) {
        if (bytes.size() >= 27) check_binary_fbx_depth(bytes, file);
        return;
    }
    int depth = 0;
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        if (bytes[i] == ';')  // to the end of the line, as assimp's FBXTokenizer ends it
            i = std::min(bytes.find_first_of(std::string_view("\r\n\f\0", 4), i), bytes.size());
        else if (bytes[i] == '"')
            i = std::min(bytes.find('"', i + 1), bytes.size());
        else if (bytes[i] == '}')
            --depth;
        else if (bytes[i] == '{' && ++depth > max_nesting_depth)
            refuse_fbx_depth(file, i);
    }
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
    if (extension == ".x3d") check_xml_depth(bytes, file);
    if (extension == ".fbx") check_fbx_depth(bytes, file);
    if (extension == ".dae") check_collada_file(bytes, file);
    if (extension == ".ifc" || extension == ".stp" || extension == ".step")
        check_step_file(bytes, file, max_nesting_depth);
}

}  // namespace boxlod
