#pragma once
// Releases of the graded exercises: the student tree, the Gradescope autograder bundle and the
// GitHub Classroom configuration, with a check that nothing secret leaks into them.

#include <filesystem>
#include <string>
#include <vector>

namespace t2grader {

/// True for paths (relative to the source tree) that must never reach students: reference
/// solutions, hidden tests, wrong solutions, the hostile and template folders, the grader's
/// own test sources, build folders and git metadata.
bool is_secret_path(const std::filesystem::path& rel);

/// Copies the source tree `src` to `out`, leaving out build folders, .git and (when
/// `for_students`) every secret path. `out` must not exist or be empty.
void copy_tree(const std::filesystem::path& src, const std::filesystem::path& out, bool for_students);

/// The lines that identify secret exercise content: trimmed lines of at least 30 characters
/// of the secret files under `source_root`/exercises (is_secret_path) that appear in no other
/// file of the source tree (so that shared idioms such as a loop header are not flagged).
std::vector<std::string> secret_lines(const std::filesystem::path& source_root);

/// Every "file: line" of `tree` that contains one of `secrets` (empty when nothing leaks).
std::vector<std::string> find_leaks(const std::filesystem::path& tree, const std::vector<std::string>& secrets);

}  // namespace t2grader
