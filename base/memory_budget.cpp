#include "base/memory_budget.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <fstream>
#include <utility>

namespace boxlod {
namespace {

std::atomic<double> budget{0};  // 0: not set yet
std::atomic<double> held{0};    // MemoryHold's sum

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

double usable_memory() {
    double available = physical_memory();
    if (const double limit = cgroup_limit(); limit > 0) available = std::min(available, limit);
    if (rlimit limit{}; getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
        available = std::min(available, double(limit.rlim_cur));
    return available;
}

double default_memory_budget() { return usable_memory() / 2; }

double memory_budget() {
    static const double fallback = default_memory_budget();  // read once: frames check it often
    const double set = budget.load();
    return set > 0 ? set : fallback;
}

// A budget beyond what the process may use would let a request through to run out of memory: the
// estimate is then checked against what there is.
void set_memory_budget(double bytes) { budget.store(std::min(bytes, usable_memory())); }

std::string memory_text(double bytes) {
    char text[32];
    if (bytes >= 1e9)
        std::snprintf(text, sizeof text, "%.3g GB", bytes / 1e9);
    else
        std::snprintf(text, sizeof text, "%.3g MB", bytes / 1e6);
    return text;
}

MemoryHold::MemoryHold(double bytes) { set(bytes); }
MemoryHold::~MemoryHold() { set(0); }
MemoryHold::MemoryHold(MemoryHold&& other) noexcept : bytes_(std::exchange(other.bytes_, 0)) {}
MemoryHold& MemoryHold::operator=(MemoryHold&& other) noexcept {
    set(0);
    bytes_ = std::exchange(other.bytes_, 0);
    return *this;
}
void MemoryHold::set(double bytes) {
    held.fetch_add(bytes - bytes_);
    bytes_ = bytes;
}

double held_memory() { return std::max(0.0, held.load()); }

void check_memory(const std::string& what, double bytes) {
    const double others = held_memory();
    if (bytes + others > memory_budget())
        throw InputError(what + " would need " + memory_text(bytes) +
                         (others > 0 ? " beside the " + memory_text(others) + " held" : std::string()) +
                         ", more than the memory budget of " + memory_text(memory_budget()) +
                         " (--max-memory)");
}

}  // namespace boxlod
