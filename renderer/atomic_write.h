// Files appear whole or not at all: write to a temporary name beside the
// target, then rename (DESIGN.md: Files).
#pragma once
#include <cstdint>
#include <functional>
#include <span>
#include <string>

namespace boxlod {

// Calls write(temporary_path), then renames it to path. If write throws, the
// temporary file is removed and the exception passes on.
void write_atomically(const std::string& path, const std::function<void(const std::string&)>& write);

void write_file_atomically(const std::string& path, std::span<const std::uint8_t> bytes);
void write_text_atomically(const std::string& path, const std::string& text);

}  // namespace boxlod
