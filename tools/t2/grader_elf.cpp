// Reading untrusted objects: see grader_elf.hpp.
#include "grader_elf.hpp"

#include <elf.h>

#include <cctype>
#include <cstring>
#include <optional>
#include <set>
#include <string_view>

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

// All the names of one object together may not be longer than this: a name is never cut, and
// a table of a million symbols naming the same megabyte of text costs nothing to refuse.
constexpr std::uint64_t kNameBudget = 64ull << 20;

// The NUL-terminated string at `off` of the string table [base, base + size), whole, charged
// to `budget`; nullopt when the table is broken or the budget runs out.
std::optional<std::string_view> str_at(const std::string& bytes, std::uint64_t base, std::uint64_t size,
                                       std::uint64_t off, std::uint64_t& budget) {
  if (base > bytes.size() || size > bytes.size() - base || off >= size) return std::nullopt;
  const char* p = bytes.data() + base + off;
  const std::uint64_t room = std::min<std::uint64_t>(size - off, budget + 1);
  const size_t n = strnlen(p, static_cast<size_t>(room));
  if (n == room) return std::nullopt;  // no NUL within the table, or over budget
  budget -= n;
  return std::string_view(p, n);
}

// Reads the name a mangled symbol (Itanium C++ ABI) names, as "t2::orient", without demangling
// it: a linear scan that stops at the name's first template arguments, parameters or anything
// it does not know. Operators read as "operator==", ABI tags ([abi:cxx11]) are dropped.
// Demangling proper can take time and memory exponential in the symbol's length (each
// substitution repeats a whole type), which a hostile symbol exploits.
class MangledName {
 public:
  explicit MangledName(std::string_view s) : s_(s) {}
  // The qualified name, "" when none could be read.
  std::string read() {
    if (s_.substr(0, 2) != "_Z") return std::string(s_.substr(0, s_.find('@')));  // C: the name itself
    i_ = 2;
    encoding(0);
    std::string r;
    for (const auto& c : parts_) r += (r.empty() ? "" : "::") + c;
    return r;
  }

 private:
  std::string_view s_;
  size_t i_ = 0;
  std::vector<std::string> parts_;

  char peek(size_t k = 0) const { return i_ + k < s_.size() ? s_[i_ + k] : '\0'; }
  bool eat(std::string_view w) {
    if (s_.substr(i_, w.size()) != w) return false;
    i_ += w.size();
    return true;
  }
  bool digit() const { return std::isdigit(static_cast<unsigned char>(peek())) != 0; }
  bool number() {  // [n] <digits>
    eat("n");
    if (!digit()) return false;
    while (digit()) ++i_;
    return true;
  }
  bool source_name(std::string* out) {  // <length> <identifier>
    size_t n = 0;
    if (!digit()) return false;
    for (int k = 0; digit(); ++k) {
      if (k == 9) return false;
      n = n * 10 + static_cast<size_t>(peek() - '0');
      ++i_;
    }
    if (n == 0 || n > s_.size() - i_) return false;
    if (out) *out = std::string(s_.substr(i_, n));
    i_ += n;
    return true;
  }
  void abi_tags() {
    while (peek() == 'B' && std::isdigit(static_cast<unsigned char>(peek(1)))) {
      ++i_;
      if (!source_name(nullptr)) return;
    }
  }
  static const char* operator_word(std::string_view code) {
    static const std::pair<const char*, const char*> ops[] = {
        {"nw", "new"}, {"na", "new[]"}, {"dl", "delete"}, {"da", "delete[]"}, {"aw", "co_await"},
        {"ps", "+"}, {"ng", "-"}, {"ad", "&"}, {"de", "*"}, {"co", "~"}, {"pl", "+"}, {"mi", "-"},
        {"ml", "*"}, {"dv", "/"}, {"rm", "%"}, {"an", "&"}, {"or", "|"}, {"eo", "^"}, {"aS", "="},
        {"pL", "+="}, {"mI", "-="}, {"mL", "*="}, {"dV", "/="}, {"rM", "%="}, {"aN", "&="},
        {"oR", "|="}, {"eO", "^="}, {"ls", "<<"}, {"rs", ">>"}, {"lS", "<<="}, {"rS", ">>="},
        {"eq", "=="}, {"ne", "!="}, {"lt", "<"}, {"gt", ">"}, {"le", "<="}, {"ge", ">="},
        {"ss", "<=>"}, {"nt", "!"}, {"aa", "&&"}, {"oo", "||"}, {"pp", "++"}, {"mm", "--"},
        {"cm", ","}, {"pm", "->*"}, {"pt", "->"}, {"cl", "()"}, {"ix", "[]"}, {"qu", "?"}};
    for (const auto& [c, w] : ops)
      if (code == c) return w;
    return nullptr;
  }
  // One <unqualified-name> appended to parts_; false at anything else (the name ends there).
  bool unqualified() {
    eat("L");  // internal linkage (GCC)
    std::string n;
    if (digit()) {
      if (!source_name(&n)) return false;
    } else if (std::islower(static_cast<unsigned char>(peek()))) {
      if (eat("li")) {
        if (!source_name(&n)) return false;
        n = "operator\"\" " + n;
      } else if (const char* w = operator_word(s_.substr(i_, 2))) {
        i_ += 2;
        n = std::string("operator") + (std::isalpha(static_cast<unsigned char>(w[0])) ? " " : "") + w;
      } else {
        return false;  // cv (conversion), vendor operators: not names a manifest lists
      }
    } else {
      return false;  // constructors, destructors, unnamed types, lambdas: the prefix names them
    }
    parts_.push_back(std::move(n));
    abi_tags();
    return true;
  }
  void standard_prefix() {  // St, Sa, Ss, ... all name std
    parts_.push_back("std");
    i_ += 2;
  }
  // <name>: nested, local, std:: or unscoped.
  void name(int depth) {
    if (eat("N")) {
      while (peek() == 'r' || peek() == 'V' || peek() == 'K') ++i_;
      if (peek() == 'R' || peek() == 'O' || peek() == 'H') ++i_;
      if (peek() == 'S' && std::islower(static_cast<unsigned char>(peek(1)))) standard_prefix();
      while (unqualified()) {
      }
    } else if (eat("Z")) {
      encoding(depth + 1);  // an entity local to a function is named by that function
    } else if (peek() == 'S' && std::islower(static_cast<unsigned char>(peek(1)))) {
      const bool st = peek(1) == 't';
      standard_prefix();
      if (st) unqualified();
    } else {
      unqualified();
    }
  }
  // <encoding> or <special-name> (virtual tables, type information, guard variables, thunks).
  void encoding(int depth) {
    if (depth > 8) return;
    if (eat("TV") || eat("TT") || eat("TI") || eat("TS") || eat("TW") || eat("TH") || eat("GV") || eat("GR")) {
      while (peek() && std::strchr("PRKVO", peek())) ++i_;
      name(depth);
    } else if (eat("Th")) {
      if (number() && eat("_")) encoding(depth + 1);
    } else if (eat("Tv")) {
      if (number() && eat("_") && number() && eat("_")) encoding(depth + 1);
    } else if (eat("Tc")) {
      for (int k = 0; k < 2; ++k) {
        if (eat("h")) {
          if (!number() || !eat("_")) return;
        } else if (eat("v")) {
          if (!number() || !eat("_") || !number() || !eat("_")) return;
        } else {
          return;
        }
      }
      encoding(depth + 1);
    } else if (eat("GTt") || eat("GTn")) {
      encoding(depth + 1);
    } else {
      name(depth);
    }
  }
};

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
  std::uint64_t budget = kNameBudget;
  const Elf64_Shdr& names = sh[eh.e_shstrndx];
  for (const auto& s : sh) {
    const auto n = str_at(bytes, names.sh_offset, names.sh_size, s.sh_name, budget);
    if (!n) {
      o.error = "a section name outside its table, or names longer than 64 MB in all";
      return o;
    }
    o.sections.emplace_back(*n);
  }
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
      const auto name = str_at(bytes, strtab.sh_offset, strtab.sh_size, sym.st_name, budget);
      if (!name) {
        o.error = "a symbol name outside its table, or names longer than 64 MB in all";
        return o;
      }
      if (!name->empty()) o.symbols.push_back(MangledName(*name).read());
    }
  }
  o.ok = true;
  return o;
}

std::string refuse_object(const ObjectInfo& o, const std::vector<std::string>& forbidden) {
  if (!o.ok) return "the compiled object could not be read (" + o.error + ")";
  for (const auto& s : o.sections)
    if (s.rfind(".gnu.lto_", 0) == 0 || s.rfind(".gnu.debuglto_", 0) == 0)
      return fmt::format("the object holds link-time-optimization code (section {}): LTO is not allowed", s);
  std::set<std::string> named;
  for (const auto& b : o.symbols)
    for (const auto& f : forbidden)
      if (b == f || b.rfind(f + "::", 0) == 0) named.insert(f);
  if (named.empty()) return {};
  std::string list;
  for (const auto& f : named) list += (list.empty() ? "" : ", ") + f;
  return fmt::format("your code calls {}, which this exercise asks you to write yourself (forbidden: the "
                     "exercise's manifest lists the library functions that solve it); score 0",
                     list);
}

}  // namespace t2grader
