// Following one pixel (tierlift run --trace X,Y): every instruction of the pass's pixel
// listing with its destination register's value at that pixel, on the interpreter
// (cpu::trace_pixel) and on Vulkan (the pixel module instrumented to record the pixel,
// codegen::TracePixel, through vulkan::TextureSet::draw_traced), side by side, and the first
// instruction where the two differ. A translation-layer author then reads "this mad
// differs" instead of "the images differ".
//
//   ir::Result<cpu::PixelTrace> cpu = cpu::trace_pixel(pass, 64, 64, 3, 2);
//   ir::Result<vulkan::ShaderTrace> vk = trace_on_vulkan(device, pass, 64, 64, format, 3, 2);
//   PixelTraceTable t = make_trace_table(*pass.pixel_program, 3, 2, &*cpu, &*vk);
//   fmt::print("{}", format_trace_table(t));
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tierlift/cpu/draw.h"
#include "tierlift/image/image.h"
#include "tierlift/ir/program.h"
#include "tierlift/ir/result.h"
#include "tierlift/pass/pass.h"
#include "tierlift/vulkan/texture_set.h"

namespace tierlift::effects {

// One column's record of one instruction: its destination register after the last run at
// the pixel, and how many times it ran there (0: not run, and value means nothing).
struct TraceCell {
  std::array<float, 4> value{};
  uint32_t runs = 0;
};

// One instruction of the pixel listing.
struct TraceRow {
  uint32_t index = 0; // in Program::code
  uint32_t line = 0;  // source line of the instruction (0: none, e.g. a token stream)
  std::string text;   // the instruction in canonical form ("mad r0, t0, c1, c2")
  std::string dest;   // its destination register ("r0", "oC0", "a0"); empty: none
  uint8_t mask = 0xF; // its write mask: the components the columns are compared in
  std::optional<TraceCell> interpreter; // none: no interpreter column
  std::optional<TraceCell> vulkan; // none: no Vulkan column, or the module records nothing here
  bool differs = false; // both recorded, and they ran a different number of times or left
                        // different bits in a written component (two NaNs count as equal)
};

struct PixelTraceTable {
  uint32_t x = 0, y = 0;
  bool has_interpreter = false, has_vulkan = false;
  bool interpreter_covered = false, vulkan_covered = false; // a triangle drew the pixel
  std::vector<TraceRow> rows;             // every instruction of Program::code, in order
  std::optional<size_t> first_difference; // index into rows
};

// The pixel program's record on `device`: `pass` drawn into a new width × height target of
// `format`, its images uploaded as the Vulkan pass device uploads a graph's inputs (each in
// its own format, so RGBA8 images are read in place as in the run), the module instrumented
// for pixel (x, y).
ir::Result<vulkan::ShaderTrace> trace_on_vulkan(vulkan::Device& device, const pass::Pass& pass,
                                                uint32_t width, uint32_t height, img::Format format,
                                                uint32_t x, uint32_t y);

// The side-by-side table of `program` (the pass's pixel program both columns ran) at pixel
// (x, y). Either column may be absent (nullptr): --backend cpu has the interpreter's only.
PixelTraceTable make_trace_table(const ir::Program& program, uint32_t x, uint32_t y,
                                 const cpu::PixelTrace* interpreter,
                                 const vulkan::ShaderTrace* vulkan);

// A value as the table prints it: "(1, 0.5, -0, nan)", each component %.9g, so identical
// bits print identically; with `bits`, each component's hex pattern follows
// ("(1 0x3f800000, …)"), which shows differing bits that print alike (NaN payloads).
std::string format_value(const std::array<float, 4>& v, bool bits = false);

// The table as text: one line per instruction, then "first difference: line 7 `mad r0, …`:
// interpreter r0 = (…), Vulkan r0 = (…)" (with the bits) or that the columns agree.
std::string format_trace_table(const PixelTraceTable& table);

} // namespace tierlift::effects
