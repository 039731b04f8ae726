#include "renderer/atomic_write.h"

#include "renderer/input_error.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace boxlod {

void write_atomically(const std::string& path, const std::function<void(const std::string&)>& write) {
    namespace fs = std::filesystem;
    fs::path target(path);
    // The pid keeps two processes writing the same file from sharing a temporary.
    fs::path temporary = target;
    temporary += ".tmp" + std::to_string(::getpid());
    try {
        write(temporary.string());
        fs::rename(temporary, target);
    } catch (...) {
        std::error_code ignored;
        fs::remove(temporary, ignored);
        throw;
    }
}

void write_file_atomically(const std::string& path, std::span<const std::uint8_t> bytes) {
    write_atomically(path, [&](const std::string& temporary) {
        std::ofstream out(temporary, std::ios::binary);
        out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
        out.close();
        if (!out) throw_input_error(path, "", "cannot write file");
    });
}

void write_text_atomically(const std::string& path, const std::string& text) {
    write_file_atomically(path, {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
}

}  // namespace boxlod
