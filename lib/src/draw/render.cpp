// Display lists of the models (see t2/draw/render.hpp). Work in progress.
#include "t2/draw/render.hpp"
#include "t2/error.hpp"

namespace t2::draw {
std::vector<Shape> display_list(const Figure&, const PlaneView&) { throw std::logic_error("not implemented"); }
std::vector<Shape> display_list(const Figure&, const SphereView&) { throw std::logic_error("not implemented"); }
std::vector<Shape> display_list(const Figure&, const T1View&) { throw std::logic_error("not implemented"); }
Format format_of(const std::filesystem::path&) { throw std::logic_error("not implemented"); }
std::string render(const Figure&, const PlaneView&, Format) { throw std::logic_error("not implemented"); }
std::string render(const Figure&, const SphereView&, Format) { throw std::logic_error("not implemented"); }
std::string render(const Figure&, const T1View&, Format) { throw std::logic_error("not implemented"); }
std::string render_both(const Figure&, const PlaneView&, const SphereView&, Format) { throw std::logic_error("not implemented"); }
bool save(const Figure&, const PlaneView&, const std::filesystem::path&) { throw std::logic_error("not implemented"); }
bool save(const Figure&, const SphereView&, const std::filesystem::path&) { throw std::logic_error("not implemented"); }
bool save(const Figure&, const T1View&, const std::filesystem::path&) { throw std::logic_error("not implemented"); }
bool save_both(const Figure&, const PlaneView&, const SphereView&, const std::filesystem::path&) { throw std::logic_error("not implemented"); }
std::filesystem::path figures_dir(int argc, char** argv, const std::filesystem::path& fallback) {
  for (int i = 1; i + 1 < argc; ++i)
    if (std::string(argv[i]) == "--figures") return argv[i + 1];
  return fallback;
}
}  // namespace t2::draw
