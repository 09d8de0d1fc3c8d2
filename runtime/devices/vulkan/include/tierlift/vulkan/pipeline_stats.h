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

// Time spent in the queue submissions that carry draws (submitted and waited for), every
// device of this process so far, in milliseconds. lavapipe compiles a pipeline's shaders
// to machine code (llvmpipe's JIT) at the first draw that uses it, not in
// vkCreateGraphicsPipelines: pipeline creation plus the first draw is what the driver must
// spend before a pipeline has drawn anything.
double draw_submission_ms();
// The same in CPU time of the whole process (all threads) while the submission ran: the
// JIT and the rasterising run on lavapipe's queue thread while the caller waits.
double draw_submission_cpu_ms();
// The number of those submissions.
long draw_submissions();
// Every queue submission (each waited for: uploads, draws, read-backs), every device of this
// process so far: each is a hand-over to lavapipe's queue thread and back.
long queue_submissions();

} // namespace tierlift::vulkan
