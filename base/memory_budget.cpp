#include "base/memory_budget.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <fstream>

namespace boxlod {
namespace {

std::atomic<double> budget{0};  // 0: not set yet

double physical_memory() { return double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGESIZE)); }

// cgroup v2's limit of this process's group ("max": none), or 0.
double cgroup_limit() {
    std::ifstream group("/proc/self/cgroup");
    std::string line, path;
    while (std::getline(group, line))
        if (line.starts_with("0::")) path = line.substr(3);
    std::ifstream limit("/sys/fs/cgroup" + path + "/memory.max");
    double bytes = 0;
    return limit >> bytes ? bytes : 0;
}

}  // namespace

Option max_memory_option() {
    return {
        "max-memory", "GB",
        "refuse a request estimated to need more memory than this (default: half of this machine's memory)",
        max_memory_range};
}

double default_memory_budget() {
    double available = physical_memory();
    if (const double limit = cgroup_limit(); limit > 0) available = std::min(available, limit);
    if (rlimit limit{}; getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
        available = std::min(available, double(limit.rlim_cur));
    return available / 2;
}

double memory_budget() {
    static const double fallback = default_memory_budget();  // read once: frames check it often
    const double set = budget.load();
    return set > 0 ? set : fallback;
}

void set_memory_budget(double bytes) { budget.store(bytes); }

std::string memory_text(double bytes) {
    char text[32];
    if (bytes >= 1e9)
        std::snprintf(text, sizeof text, "%.3g GB", bytes / 1e9);
    else
        std::snprintf(text, sizeof text, "%.3g MB", bytes / 1e6);
    return text;
}

void check_memory(const std::string& what, double bytes) {
    if (bytes > memory_budget())
        throw InputError(what + " would need " + memory_text(bytes) + ", more than the memory budget of " +
                         memory_text(memory_budget()) + " (--max-memory)");
}

}  // namespace boxlod
