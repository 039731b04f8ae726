#include "base/command_registry.h"

#include "base/input_error.h"
#include "base/memory_budget.h"

#include <cstdio>
#include <exception>
#include <new>
#include <string>

namespace boxlod {
namespace {

void print_overview(const std::vector<Subcommand>& subcommands) {
    std::printf(
        "usage: boxlod COMMAND [arguments] [options]\n\n"
        "Textured-box level of detail for hierarchical (procedural) architecture.\n\ncommands:\n");
    for (const auto& s : subcommands) {  // the first sentence of each summary
        const std::string& summary = s.command.summary;
        std::size_t sentence = summary.find(". "), line = summary.find('\n');
        std::string first = sentence < line ? summary.substr(0, sentence + 1) : summary.substr(0, line);
        std::printf("  %-10s %s\n", s.command.name.c_str(), first.c_str());
    }
    std::printf(
        "\n'boxlod COMMAND --help' describes a command's options.\n"
        "Exit status: 0 success, 2 bad input, usage or out of memory, 1 internal failure.\n");
}

}  // namespace

int run_subcommands(const std::vector<Subcommand>& subcommands, int argc, char** argv) {
    std::vector<std::string> words(argv + 1, argv + argc);
    if (words.empty() || words[0] == "--help" || words[0] == "-h" || words[0] == "help") {
        print_overview(subcommands);
        return words.empty() ? 2 : 0;
    }
    try {
        for (const auto& s : subcommands) {
            if (s.command.name != words[0]) continue;
            Command command = s.command;  // with the options every command takes
            command.options = with_options(command.options, {max_memory_option()});
            Arguments arguments =
                parse_arguments(command, std::vector<std::string>(words.begin() + 1, words.end()));
            if (arguments.has("help")) {
                std::fputs(help_text(command).c_str(), stdout);
                return 0;
            }
            if (arguments.has("max-memory")) set_memory_budget(arguments.number("max-memory", 0) * 1e9);
            return s.run(arguments);
        }
        std::fprintf(stderr, "boxlod: unknown command '%s' (see boxlod --help)\n", words[0].c_str());
        return 2;
    } catch (const InputError& error) {
        // Messages that already name the command ("boxlod sweep: ...") get no second prefix.
        std::string message = error.what();
        std::fprintf(stderr, "%s%s\n", message.starts_with("boxlod ") ? "" : "boxlod: ", message.c_str());
        return 2;
    } catch (const std::bad_array_new_length& error) {  // a size computed wrong: a bug, not a request
        std::fprintf(stderr, "boxlod: internal error: %s\n", error.what());
        return 1;
    } catch (const std::bad_alloc&) {
        // What the memory budget's estimates missed (base/memory_budget.h): a request too large, not a bug.
        std::fprintf(stderr,
                     "boxlod: %s: out of memory: the request needs more than this machine gives "
                     "(smaller sizes or fewer levels need less)\n",
                     words[0].c_str());
        return 2;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "boxlod: internal error: %s\n", error.what());
        return 1;
    }
}

}  // namespace boxlod
