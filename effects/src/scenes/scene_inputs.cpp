// scene_input_files (scene.h): what a scene reads, so that `glow -o` and `report -o` never
// write over it.
#include <algorithm>

#include "tierlift/assembly/load.h"
#include "tierlift/assembly/preprocessor.h"
#include "tierlift/effects/scenes/scene.h"
#include "tierlift/io/bounded_read.h"

namespace tierlift::effects {
namespace {

void add(std::vector<std::string>& out, const std::string& path) {
  if (path.empty() || path == "-" || path.starts_with("builtin:")) return;
  if (std::find(out.begin(), out.end(), path) == out.end()) out.push_back(path);
}

// The files `path`'s #include lines open (none for a token stream, or a file that cannot
// be read: the run reports that itself).
std::vector<std::string> includes_of(const std::string& path, const ListingOptions& listing) {
  ir::Result<std::string> text = io::read_bounded(path, io::kListingCap);
  if (!text || assembly::detect_listing_form(*text) != assembly::ListingForm::Text) return {};
  ir::SourceManager sm;
  const uint32_t file = sm.add(path, std::move(*text));
  assembly::ParseOptions options;
  options.defines = listing.defines;
  options.include_dirs = listing.include_dirs;
  ir::DiagnosticSink ignored; // the run parses the listing again and says what is wrong
  assembly::preprocess(file, sm, ignored, options);
  return assembly::included_files(sm);
}

} // namespace

std::vector<std::string> scene_input_files(const Scene& scene) {
  std::vector<std::string> out;
  add(out, scene.file);
  add(out, scene.image);
  const EffectParams& p = scene.params;
  add(out, p.context.glow_image_file);
  add(out, p.context.fog.depth_file);
  for (const auto& [builtin, file] : p.listing_files) {
    add(out, file);
    for (const std::string& inc : includes_of(file, p.listing_options)) add(out, inc);
  }
  add(out, scene.glsl.horizontal); // GLSL: glslang is given no #include
  add(out, scene.glsl.vertical);
  for (const std::string* twin : {&scene.glsl.horizontal_twin, &scene.glsl.vertical_twin}) {
    add(out, *twin);
    for (const std::string& inc : includes_of(*twin, p.listing_options)) add(out, inc);
  }
  return out;
}

} // namespace tierlift::effects
