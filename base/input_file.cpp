#include "base/input_file.h"

#include "base/input_error.h"

#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace boxlod {

namespace {

std::string with_article(const std::string& kind) {  // "a model file", "an image file"
    return (kind.find_first_of("aeiou") == 0 ? "an " : "a ") + kind;
}

}  // namespace

std::size_t check_input_file(const std::string& path, const std::string& kind) {
    namespace fs = std::filesystem;
    if (path.empty())
        throw_input_error("''", "", "an empty file name where " + with_article(kind) + " was expected");
    std::error_code error;
    fs::file_status status = fs::status(path, error);
    if (status.type() == fs::file_type::not_found) throw_input_error(path, "", "no such file");
    if (error) throw_input_error(path, "", "cannot open " + kind + ": " + error.message());
    if (status.type() == fs::file_type::directory)
        throw_input_error(path, "", "is a directory, not " + with_article(kind));
    if (status.type() != fs::file_type::regular)
        throw_input_error(path, "", "is not a regular file (" + with_article(kind) + " was expected)");
    std::ifstream probe(path, std::ios::binary);
    if (!probe) throw_input_error(path, "", "cannot open " + kind + ": " + std::strerror(errno));
    std::uintmax_t size = fs::file_size(path, error);
    if (error) throw_input_error(path, "", "cannot read " + kind + ": " + error.message());
    if (size > max_input_file_bytes)
        throw_input_error(path, "",
                          "is " + std::to_string(size >> 20) + " MiB, more than the " +
                              std::to_string(max_input_file_bytes >> 20) + " MiB " + with_article(kind) +
                              " may have");
    return std::size_t(size);
}

std::string read_input_file(const std::string& path, const std::string& kind) {
    check_input_file(path, kind);
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw_input_error(path, "", "cannot read " + kind);
    return std::move(text).str();
}

std::string lowercase_extension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    return extension;
}

}  // namespace boxlod
