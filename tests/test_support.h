// Small helpers shared by the tests: scratch folders, files, running the CLI.
#pragma once
#include "base/input_error.h"
#include "base/memory_budget.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

#include <unistd.h>

namespace boxlod::test {

// Gives the process back its default memory budget when a test that sets one ends.
struct MemoryBudgetScope {
    ~MemoryBudgetScope() { set_memory_budget(0); }
};

// The message of the InputError that run() throws, "" when it throws none.
template <typename Run>
std::string input_error_of(Run run) {
    try {
        run();
    } catch (const InputError& error) {
        return error.what();
    }
    return "";
}

// The test program's own folder in the temporary folder, removed when the program ends (a forked
// child leaves by _exit and removes nothing): tests leave nothing behind, and programs running side
// by side (ctest -j) never share a folder.
inline const std::filesystem::path& scratch_root() {
    struct Root {
        std::filesystem::path path =
            std::filesystem::temp_directory_path() / ("boxlod_test_" + std::to_string(::getpid()));
        ~Root() {
            std::error_code ignored;
            std::filesystem::remove_all(path, ignored);
        }
    };
    static const Root root;
    return root.path;
}

// A fresh, empty folder for one test.
inline std::filesystem::path scratch_folder(const std::string& name) {
    auto path = scratch_root() / name;
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
    return path;
}

inline void write_text(const std::filesystem::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

inline std::string read_text(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// `text` with its first `from` made `to` (a test's edit of a real file); a
// failure when `from` is not there, since the edit would change nothing.
inline std::string replaced_once(std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << "'" << from << "' is not in the text";
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

inline std::string base64(const std::vector<std::uint8_t>& bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        std::uint32_t v = bytes[i] << 16 | (i + 1 < bytes.size() ? bytes[i + 1] << 8 : 0) |
                          (i + 2 < bytes.size() ? bytes[i + 2] : 0);
        out += digits[v >> 18 & 63];
        out += digits[v >> 12 & 63];
        out += i + 1 < bytes.size() ? digits[v >> 6 & 63] : '=';
        out += i + 2 < bytes.size() ? digits[v & 63] : '=';
    }
    return out;
}

template <typename T>
void append_bytes(std::vector<std::uint8_t>& out, std::initializer_list<T> values) {
    for (T v : values) {
        auto* p = reinterpret_cast<const std::uint8_t*>(&v);
        out.insert(out.end(), p, p + sizeof(T));
    }
}

// The FZK-Haus IFC model shipped by Debian's assimp-testmodels.
inline const char* fzk_haus_ifc = "/usr/share/assimp/models/IFC/AC14-FZK-Haus.ifc";

// A model of ../shared/models beside the checkout (its README), `name` under
// it; the tests that read one skip where it is absent.
inline std::filesystem::path shared_model(const std::string& name) {
    return (std::filesystem::path(BOXLOD_TEST_DATA) / ".." / ".." / ".." / "shared" / "models" / name)
        .lexically_normal();
}

}  // namespace boxlod::test
