#include "base/child_process.h"

#include "base/input_error.h"
#include "base/key_values.h"
#include "base/memory_budget.h"

#include <fcntl.h>
#include <malloc.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <new>
#include <stdexcept>
#include <thread>
#include <utility>

namespace boxlod {
namespace {

// The child's answer: one tag byte, then the payload.
constexpr char answer_bytes = 'M', answer_input_error = 'E', answer_other_error = 'X';

void write_all(int fd, const char* data, std::size_t size) {
    while (size > 0) {
        const ssize_t written = ::write(fd, data, size);
        if (written < 0 && errno == EINTR) continue;
        if (written <= 0) return;  // the parent is gone: nothing to tell
        data += written;
        size -= std::size_t(written);
    }
}

// Limits the address space to what the child uses now plus `extra` bytes. Off
// under AddressSanitizer, whose shadow memory needs terabytes of address space.
void limit_address_space(std::size_t extra) {
#if !defined(__SANITIZE_ADDRESS__)
    long pages = 0;
    rlimit limit{};
    std::ifstream statm("/proc/self/statm");
    if (extra == 0 || !(statm >> pages) || ::getrlimit(RLIMIT_AS, &limit) != 0) return;
    const rlim_t wanted = rlim_t(pages) * rlim_t(::getpagesize()) + rlim_t(extra);
    if (limit.rlim_cur == RLIM_INFINITY || wanted < limit.rlim_cur) limit.rlim_cur = wanted;
    ::setrlimit(RLIMIT_AS, &limit);
#else
    (void)extra;
#endif
}

[[noreturn]] void run_child(int fd, const std::function<std::string()>& work, const ChildLimits& limits,
                            const std::string& file, pid_t parent) {
    // The parent's interrupt handlers clean up the parent's files: not the child's business. A fault
    // kills the child by its signal, which the parent names (also under a sanitizer's handlers). The
    // forking thread's mask (the parent waits for interrupts with them blocked) is not the child's
    // either, and the child dies with the parent: an interrupted boxlod leaves no reader running.
    for (int signal : {SIGINT, SIGTERM, SIGHUP, SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT})
        std::signal(signal, SIG_DFL);
    sigset_t none;
    sigemptyset(&none);
    ::pthread_sigmask(SIG_SETMASK, &none, nullptr);
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(1);  // it died before prctl
    // The parent's freed heap would come back to the child page by page as copies
    // (copy-on-write pages of the parent's heap count against the child); given back, it comes back as fresh
    // pages.
    ::malloc_trim(0);
    limit_address_space(limits.extra_address_space);
    char tag = answer_bytes;
    std::string payload;
    try {
        payload = work();
    } catch (const InputError& error) {
        tag = answer_input_error;
        payload = error.what();
    } catch (const std::bad_alloc&) {
        tag = answer_input_error;
        payload = file + ": reading it would take more than " +
                  std::to_string(limits.extra_address_space >> 20) + " MiB (counts in the file too large?)";
    } catch (const std::exception& error) {
        tag = answer_other_error;
        payload = error.what();
    } catch (...) {
        tag = answer_other_error;
        payload = "unknown exception";
    }
    const std::uint64_t size = payload.size();
    write_all(fd, &tag, 1);
    write_all(fd, reinterpret_cast<const char*>(&size), sizeof size);
    write_all(fd, payload.data(), payload.size());
    ::close(fd);  // the parent has its answer now, not after this process's memory is torn down
    ::_exit(0);   // no destructors, no atexit handlers, no flushing of the parent's stdio buffers
}

// All the child writes on `fd` until it closes it; {what was read, whether the deadline passed first}.
std::pair<std::string, bool> read_answer(int fd, std::chrono::steady_clock::time_point deadline) {
    std::string answer;
    for (char buffer[65536];;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            deadline - std::chrono::steady_clock::now());
        pollfd poll_fd{fd, POLLIN, 0};
        const int ready = ::poll(&poll_fd, 1, int(std::max<long long>(left.count(), 0)));
        if (ready < 0 && errno == EINTR) continue;
        if (ready == 0) return {answer, true};
        const ssize_t got = ::read(fd, buffer, sizeof buffer);
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) return {answer, false};
        answer.append(buffer, std::size_t(got));
    }
}

}  // namespace

std::string run_in_child(const std::function<std::string()>& work, const ChildLimits& limits,
                         const std::string& file, const std::string& reader) {
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
    const pid_t parent = ::getpid(), pid = ::fork();
    if (pid < 0) {
        ::close(fds[0]);
        ::close(fds[1]);
        throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
    }
    if (pid == 0) {
        ::close(fds[0]);
        run_child(fds[1], work, limits, file, parent);
    }
    ::close(fds[1]);
    const auto deadline =
        std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                               std::chrono::duration<double>(limits.seconds));
    auto [answer, timed_out] = read_answer(fds[0], deadline);
    ::close(fds[0]);
    const std::size_t header = 1 + sizeof(std::uint64_t);
    std::uint64_t size = 0;
    if (answer.size() >= header) std::memcpy(&size, answer.data() + 1, sizeof size);
    if (!timed_out && answer.size() >= header && answer.size() - header == size) {
        // A whole answer: the child only exits now; reap it without waiting for its memory to go.
        std::thread([pid] {
            while (::waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
            }
        }).detach();
    } else {
        if (timed_out) ::kill(pid, SIGKILL);
        int status = 0;
        while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
        }
        if (timed_out)
            throw_input_error(file, "",
                              reader + " took longer than " + format_number(limits.seconds) + " s; stopped");
        if (WIFSIGNALED(status))
            throw_input_error(file, "",
                              reader + " crashed on this file (" + ::strsignal(WTERMSIG(status)) + ")");
        throw_input_error(
            file, "",
            reader + " ended without an answer (exit status " + std::to_string(WEXITSTATUS(status)) + ")");
    }
    const char tag = answer[0];
    answer.erase(0, header);
    if (tag == answer_input_error) throw InputError(answer);
    if (tag == answer_other_error) throw std::runtime_error(answer);
    return answer;
}

namespace {

// A process's resident memory, bytes (the second field of /proc/PID/statm); 0 if unknown.
double resident_bytes(pid_t pid) {
    std::ifstream statm("/proc/" + std::to_string(pid) + "/statm");
    double size = 0, resident = 0;
    return statm >> size >> resident ? resident * double(::sysconf(_SC_PAGESIZE)) : 0;
}

// What the program writes on `fd` until it closes it; its resident memory is looked at every 20 ms
// (limits.resident_bytes), the program killed and refused when it holds more.
std::string program_output(int fd, pid_t pid, const ChildLimits& limits, const std::string& file,
                           const std::string& reader) {
    std::string output;
    auto checked = std::chrono::steady_clock::now();
    for (char buffer[65536];;) {
        pollfd poll_fd{fd, POLLIN, 0};
        const int ready = ::poll(&poll_fd, 1, limits.resident_bytes > 0 ? 20 : -1);
        if (limits.resident_bytes > 0 &&
            std::chrono::steady_clock::now() - checked >= std::chrono::milliseconds(20)) {
            checked = std::chrono::steady_clock::now();
            if (resident_bytes(pid) > limits.resident_bytes) {
                ::kill(pid, SIGKILL);
                while (::waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
                }
                throw_input_error(file, "",
                                  reader + " grew past the memory budget of " +
                                      memory_text(limits.resident_bytes) + " (--max-memory); stopped");
            }
        }
        if (ready == 0 || (ready < 0 && errno == EINTR)) continue;
        const ssize_t got = ::read(fd, buffer, sizeof buffer);
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) return output;
        output.append(buffer, std::size_t(got));
    }
}

// In the child of run_in_child: the program with its pipes, and what it wrote on descriptor 3.
std::string run_program(const std::vector<std::string>& command, const std::string& input,
                        const ChildLimits& limits, const std::string& file, const std::string& reader) {
    int to_program[2], from_program[2];
    if (::pipe(to_program) != 0 || ::pipe(from_program) != 0)
        throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
    const pid_t parent = ::getpid();
    const pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
    if (pid == 0) {
        ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // killed with the reading child (a timeout, boxlod interrupted)
        if (::getppid() != parent) ::_exit(1);  // it died before prctl
        const int null = ::open("/dev/null", O_WRONLY);
        ::dup2(to_program[0], 0);
        ::dup2(null, 1);
        ::dup2(null, 2);
        ::dup2(from_program[1], 3);
        for (int fd : {to_program[0], to_program[1], from_program[0], from_program[1], null})
            if (fd > 3) ::close(fd);
        std::vector<char*> argv;
        for (const std::string& word : command) argv.push_back(const_cast<char*>(word.c_str()));
        argv.push_back(nullptr);
        ::execvp(argv[0], argv.data());
        ::_exit(127);
    }
    ::close(to_program[0]);
    ::close(from_program[1]);
    std::signal(SIGPIPE, SIG_IGN);  // a program that stops reading early: its answer says why
    write_all(to_program[1], input.data(), input.size());
    ::close(to_program[1]);
    const std::string output = program_output(from_program[0], pid, limits, file, reader);
    ::close(from_program[0]);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (WIFEXITED(status) && WEXITSTATUS(status) == 127 && output.empty())
        throw_input_error(file, "", reader + " needs '" + command[0] + "', which is not installed");
    if (WIFSIGNALED(status))
        throw_input_error(file, "", reader + " crashed on this file (" + ::strsignal(WTERMSIG(status)) + ")");
    return output;
}

}  // namespace

std::string run_program_in_child(const std::vector<std::string>& command, const std::string& input,
                                 const ChildLimits& limits, const std::string& file,
                                 const std::string& reader) {
    return run_in_child([&] { return run_program(command, input, limits, file, reader); }, limits, file,
                        reader);
}

}  // namespace boxlod
