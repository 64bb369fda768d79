#pragma once
// The grader's cache (build/<tree>/grader-cache): files the trusted grader made once (trusted
// objects and programs, the precompiled allowed headers, the include views' system-header lists),
// each stored as <stem>-<key> beside its SHA-256, verified on every use and made again when
// missing or changed. Only this process's user may write the folder (else the run's private
// folder is used); the sandbox never sees it (one verified file, the precompiled header, is bound
// read-only into the compiler's sandbox).

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace t2grader {

namespace fs = std::filesystem;

/// The whole content of a file ("" when it cannot be read).
std::string read_text(const fs::path& p);

/// FNV-1a of `s`, continuing from `h` (the cache keys).
std::uint64_t fnv1a(const std::string& s, std::uint64_t h = 1469598103934665603ull);

/// The standard output of a trusted command ("" when it fails), within 60 s.
std::string run_out(std::vector<std::string> argv);

/// The SHA-256 of a file in hex ("" when it cannot be read); OpenSSL's when installed (it uses
/// the CPU's SHA instructions: 0.05 s for a 55 MB precompiled header, sha256sum 0.22 s).
std::string sha256(const fs::path& p);

/// The cached file `stem`-`key`, verified by its SHA-256; made by `make(tmp)` when missing or
/// changed (`tmp` in the same folder, renamed into place). `work`: the run's private folder, the
/// cache when the shared one is not ours alone to write.
fs::path cached(const fs::path& work, const std::string& stem, std::uint64_t key,
                const std::function<void(const fs::path&)>& make);

}  // namespace t2grader
