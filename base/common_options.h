// The options many commands share, each declared once: --json with the
// report it selects, and --threads.
#pragma once
#include "base/command_line.h"
#include "base/key_values.h"

#include <string>

namespace boxlod {

// --json: the report as one JSON object instead of `key = value` lines.
Option json_option();

// --threads N in thread_count_range (0: all cores): "WHAT (default: DEFAULT)".
Option threads_option(const std::string& what = "threads to use",
                      const std::string& default_text = "all cores");
// The --threads given, else `absent` (0: all cores).
int threads_from(const Arguments& arguments, int absent = 0);

// A command's report on stdout, in the format --json asks for.
void print_report(const KeyValues& report, const Arguments& arguments);

}  // namespace boxlod
