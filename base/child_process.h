// Third-party code that parses untrusted bytes runs in a child process
// (docs/design.md: Errors): whatever goes wrong in there (a crash, an
// abort, memory or time running out) ends the child, never boxlod, and comes
// back as one InputError naming the file and the reader.
#pragma once
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace boxlod {

struct ChildLimits {
    std::size_t extra_address_space = 0;  // bytes the child may grow by (RLIMIT_AS); 0: no limit
    double seconds = 60;                  // wall clock, then the child is killed
    double resident_bytes = 0;  // what a program (run_program_in_child) may hold resident, then it is
                                // killed: polled, as a WebAssembly reader reserves far more address space
                                // than it uses; 0: no limit
};

// Runs `work` in a forked child and returns the bytes it returned. An
// InputError in the child is thrown again with its message; a crash, an
// abort, a limit reached or a timeout throws InputError "file: READER
// crashed (signal) ..." and the like; any other exception a runtime_error
// with its message (an internal error, as it would be in this process).
std::string run_in_child(const std::function<std::string()>& work, const ChildLimits& limits,
                         const std::string& file, const std::string& reader);

// A reader that is another program (node running web-ifc): `command` (looked
// up in PATH) run inside run_in_child with `input` on its standard input,
// its standard output and error dropped (such readers log there); returns what
// it wrote to file descriptor 3. It dies with its parent. A program that is
// not installed, or that grows past limits.resident_bytes, is an InputError
// naming it.
std::string run_program_in_child(const std::vector<std::string>& command, const std::string& input,
                                 const ChildLimits& limits, const std::string& file,
                                 const std::string& reader);

}  // namespace boxlod
