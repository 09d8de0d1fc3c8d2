// What the driver itself spends on pipelines, for benchmarks that hold the whole lift
// against it (bench/corpus_bench.cpp).
#pragma once

namespace tierlift::vulkan {

// Time spent inside vkCreateGraphicsPipelines by every device of this process so far, in
// milliseconds.
double pipeline_creation_ms();
// The same in CPU time of the calling threads (lavapipe compiles on the calling thread): the
// figure a machine shared with other work changes least.
double pipeline_creation_cpu_ms();
// The number of vkCreateGraphicsPipelines calls behind that time.
long pipeline_creations();

} // namespace tierlift::vulkan
