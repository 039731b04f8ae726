#include "base/common_options.h"

#include "base/parallel.h"

#include <cstdio>

namespace boxlod {

Option json_option() { return {"json", "", "print one JSON object instead of key = value lines"}; }

Option threads_option(const std::string& what, const std::string& default_text) {
    return {"threads", "N", what + " (default: " + default_text + ")", thread_count_range};
}

int threads_from(const Arguments& arguments, int absent) { return arguments.integer("threads", absent); }

void print_report(const KeyValues& report, const Arguments& arguments) {
    std::fputs((arguments.has("json") ? format_json(report) : format_key_values(report)).c_str(), stdout);
}

}  // namespace boxlod
