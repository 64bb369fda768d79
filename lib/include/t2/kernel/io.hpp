#pragma once
/// @file io.hpp
/// @brief Whole files: read in one call, written atomically (a reader sees the old file or the
/// whole new one, never half); and the one `trim` of the tools.

#include <filesystem>
#include <string>
#include <string_view>

namespace t2 {

/// The whole content of the file at `path`, byte for byte. Throws `std::system_error` (its
/// message "cannot read PATH: reason") when the file cannot be opened or read.
std::string read_file(const std::filesystem::path& path);

/// Writes `content` to `path` through a temporary file in the same directory and a rename, so
/// that an error (or a crash) never leaves a half-written file. Creates missing parent
/// directories. Throws `std::system_error` on failure, leaving any existing file untouched.
void write_file_atomically(const std::filesystem::path& path, std::string_view content);

/// Writes `content` only if the file does not already hold exactly that; returns true when it
/// wrote. Keeps timestamps of unchanged figures, so builds and `git status` stay quiet.
bool update_file_atomically(const std::filesystem::path& path, std::string_view content);

/// `text` without its leading and trailing white space (spaces, tabs, carriage returns, newlines).
std::string trim(std::string_view text);

}  // namespace t2
