// The image files `tierlift run` writes and reads (run_files.h).
#include "run_files.h"

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>

#include "front_end.h"

namespace tierlift::cli {

// --backend both writes the Vulkan image beside the CPU one: out.png → out-vulkan.png.
std::string vulkan_output(const std::string& output) {
  std::filesystem::path p(output);
  return (p.parent_path() / (p.stem().string() + "-vulkan")).string() + p.extension().string();
}

// The files the run reads, which no output may replace.
std::vector<std::string> input_files(const RunFlags& f, const pass::RunRequest& r) {
  std::vector<std::string> inputs{f.vs, f.ps, f.depth_in};
  for (const pass::TextureSetting& t : r.textures)
    for (const std::string& s : pass::layered_sources(t.source).sources) inputs.push_back(s);
  return inputs;
}

// Every image file the run writes, in order: -o (oC0), --output1..3 (oC1..oC3) and
// --depth-out, each followed by its Vulkan twin when both devices run (out.png →
// out-vulkan.png).
std::vector<std::string> output_files(const RunFlags& f, bool both) {
  std::vector<std::string> files;
  for (const std::string* o :
       {&f.output, &f.more_outputs[0], &f.more_outputs[1], &f.more_outputs[2], &f.depth_out}) {
    if (o->empty()) continue;
    files.push_back(*o);
    if (both && *o != "-") files.push_back(vulkan_output(*o));
  }
  return files;
}

// -o and --output1..3: never one of the run's inputs nor one another, one image for "-"
// (-o only), the Vulkan images' names free too. False after reporting why not.
bool outputs_ok(const RunFlags& f, const pass::RunRequest& req, bool both, Report& report) {
  const std::vector<std::string> inputs = input_files(f, req);
  if (!f.output.empty()) {
    std::string why = check_output(f.output, inputs, f.fe.json).message();
    if (why.empty() && f.output == "-" && both)
      why = "-o - takes one image; --backend both writes two (give -o a file)";
    if (!why.empty()) {
      report.error(f.output == "-" ? "usage" : "io", why, f.output);
      return false;
    }
  }
  if (!f.depth_out.empty() && !f.depth_out.ends_with(".pfm")) {
    report.error(
        "usage",
        "--depth-out takes a .pfm file: the depth buffer is floats, which a PNG would round",
        f.depth_out);
    return false;
  }
  std::vector<std::string> earlier;
  for (const std::string& o : output_files(f, both)) {
    if (o == "-" && o == f.output) continue; // checked above
    std::string why = o == "-" ? "--output1..3 - : standard output takes -o's image only"
                               : output_conflict(o, inputs).message();
    if (why.empty() && std::find(earlier.begin(), earlier.end(), o) != earlier.end())
      why = fmt::format("{}: two of the run's images would be written there", o);
    if (!why.empty()) {
      report.error(o == "-" ? "usage" : "io", why, o);
      return false;
    }
    earlier.push_back(o);
  }
  return true;
}

} // namespace tierlift::cli
