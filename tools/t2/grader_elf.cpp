// Reading untrusted objects: see grader_elf.hpp.
#include "grader_elf.hpp"

#include <cxxabi.h>
#include <elf.h>

#include <cstdlib>
#include <cstring>
#include <memory>
#include <set>

#include <fmt/format.h>

namespace t2grader {

namespace {

// Copies a T from bytes[off..] when it fits entirely.
template <class T>
bool at(const std::string& bytes, std::uint64_t off, T& out) {
  if (off > bytes.size() || sizeof(T) > bytes.size() - off) return false;
  std::memcpy(&out, bytes.data() + off, sizeof(T));
  return true;
}

// The NUL-terminated string at `off` of the string table [base, base + size).
std::string str_at(const std::string& bytes, std::uint64_t base, std::uint64_t size, std::uint64_t off) {
  if (base > bytes.size() || size > bytes.size() - base || off >= size) return {};
  const char* p = bytes.data() + base + off;
  const size_t n = strnlen(p, static_cast<size_t>(size - off));
  return std::string(p, std::min<size_t>(n, 4096));
}

std::string demangle(const std::string& s) {
  int status = 0;
  std::unique_ptr<char, void (*)(void*)> d(abi::__cxa_demangle(s.c_str(), nullptr, nullptr, &status), std::free);
  return status == 0 && d ? std::string(d.get()) : s;
}

}  // namespace

ObjectInfo read_object(const std::string& bytes) {
  ObjectInfo o;
  Elf64_Ehdr eh{};
  if (!at(bytes, 0, eh) || std::memcmp(eh.e_ident, ELFMAG, SELFMAG) != 0 || eh.e_ident[EI_CLASS] != ELFCLASS64 ||
      eh.e_ident[EI_DATA] != ELFDATA2LSB) {
    o.error = "not an ELF64 little-endian object";
    return o;
  }
  if (eh.e_shentsize != sizeof(Elf64_Shdr) || eh.e_shnum == 0 || eh.e_shstrndx >= eh.e_shnum) {
    o.error = "bad section table";
    return o;
  }
  std::vector<Elf64_Shdr> sh(eh.e_shnum);
  for (size_t i = 0; i < sh.size(); ++i)
    if (!at(bytes, eh.e_shoff + i * sizeof(Elf64_Shdr), sh[i])) {
      o.error = "section table outside the file";
      return o;
    }
  const Elf64_Shdr& names = sh[eh.e_shstrndx];
  for (const auto& s : sh) o.sections.push_back(str_at(bytes, names.sh_offset, names.sh_size, s.sh_name));
  for (const auto& s : sh) {
    if (s.sh_type != SHT_SYMTAB) continue;
    if (s.sh_link >= sh.size() || s.sh_entsize != sizeof(Elf64_Sym)) {
      o.error = "bad symbol table";
      return o;
    }
    const Elf64_Shdr& strtab = sh[s.sh_link];
    const std::uint64_t n = s.sh_size / sizeof(Elf64_Sym);
    if (n > 10000000) {
      o.error = "too many symbols";
      return o;
    }
    for (std::uint64_t i = 1; i < n; ++i) {
      Elf64_Sym sym{};
      if (!at(bytes, s.sh_offset + i * sizeof(Elf64_Sym), sym)) {
        o.error = "symbol table outside the file";
        return o;
      }
      const int type = ELF64_ST_TYPE(sym.st_info);
      if (type == STT_SECTION || type == STT_FILE) continue;
      const std::string name = str_at(bytes, strtab.sh_offset, strtab.sh_size, sym.st_name);
      if (!name.empty()) o.symbols.push_back(demangle(name));
    }
  }
  o.ok = true;
  return o;
}

std::string bare_name(const std::string& demangled) {
  // Drop template arguments and parameter lists (at any depth), keep the rest.
  std::string s;
  int depth = 0;
  for (size_t i = 0; i < demangled.size(); ++i) {
    const char c = demangled[i];
    // "operator<", "operator<<", "operator()" ... are names, not brackets.
    if (depth == 0 && demangled.compare(i, 8, "operator") == 0) {
      size_t j = i + 8;
      while (j < demangled.size() && std::strchr("=!<>+-*/%&|^~[]()", demangled[j]) &&
             !(demangled[j] == '<' && j + 1 < demangled.size() && std::isalpha(static_cast<unsigned char>(demangled[j + 1]))) &&
             !(demangled[j] == '(' && j > i + 8))
        ++j;
      s += demangled.substr(i, j - i);
      i = j - 1;
      continue;
    }
    if (c == '<' || c == '(') ++depth;
    else if ((c == '>' || c == ')') && depth > 0) --depth;
    else if (depth == 0) s += c;
  }
  // The qualified name is the last word ("bool t2::orient" → "t2::orient"; "... const" dropped).
  while (!s.empty() && s.back() == ' ') s.pop_back();
  if (s.size() > 6 && s.compare(s.size() - 6, 6, " const") == 0) s.resize(s.size() - 6);
  const auto sp = s.rfind(' ');
  return sp == std::string::npos ? s : s.substr(sp + 1);
}

std::string refuse_object(const ObjectInfo& o, const std::vector<std::string>& forbidden) {
  if (!o.ok) return "the compiled object could not be read (" + o.error + ")";
  for (const auto& s : o.sections)
    if (s.rfind(".gnu.lto_", 0) == 0 || s.rfind(".gnu.debuglto_", 0) == 0)
      return fmt::format("the object holds link-time-optimization code (section {}): LTO is not allowed", s);
  std::set<std::string> named;
  for (const auto& sym : o.symbols) {
    const std::string b = bare_name(sym);
    for (const auto& f : forbidden)
      if (b == f || b.rfind(f + "::", 0) == 0) named.insert(f);
  }
  if (named.empty()) return {};
  std::string list;
  for (const auto& f : named) list += (list.empty() ? "" : ", ") + f;
  return fmt::format("your code calls {}, which this exercise asks you to write yourself (forbidden: the "
                     "exercise's manifest lists the library functions that solve it); score 0",
                     list);
}

}  // namespace t2grader
