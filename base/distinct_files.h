#pragma once
// A command's outputs never overwrite its inputs or each other.

#include <string>
#include <utility>
#include <vector>

namespace boxlod {

// Outputs of one command, and the inputs it reads, name different files:
// throws InputError "PATH: --B names the same file as --A" for the first
// output of `outputs` ({option, path}, empty paths skipped) that names the
// file of an earlier entry (of `inputs`, or of `outputs`).
void check_distinct_files(const std::vector<std::pair<std::string, std::string>>& inputs,
                          const std::vector<std::pair<std::string, std::string>>& outputs);

}  // namespace boxlod
