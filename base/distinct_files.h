#pragma once
// A command's outputs never overwrite its inputs or each other.

#include <functional>
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

// An input is none of the files a command writes into `folder` (those whose
// names `written` claims), by the file it leads to or the name it has there
// (symbolic links resolved): throws InputError "INPUT: `how` would write over it".
void check_input_kept(const std::string& input, const std::string& folder,
                      const std::function<bool(const std::string& name)>& written, const std::string& how);

}  // namespace boxlod
