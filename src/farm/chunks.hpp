#pragma once
// Chunks: a job's frames cut into N contiguous parts, one per farm task
// (docs/farm.md, "Chunks"). Chunks are numbered from 0, as Slurm array
// task ids and Kubernetes completion indices are.
#include <functional>
#include <string>
#include <vector>

namespace facet {

struct ChunkChoice {
    int index = 0;
    int count = 1;
    std::string origin;  // how it was given, for errors and the log: "--chunk 2/6"
};

// "I/N" from --chunk: 0 <= I < N. Throws invalid_input naming the option.
ChunkChoice parse_chunk(const std::string& text);

// --chunk-from-env: the index from the first of SLURM_ARRAY_TASK_ID,
// JOB_COMPLETION_INDEX (Kubernetes Indexed Jobs), AWS_BATCH_JOB_ARRAY_INDEX
// that is set; the count from `count` (--chunks) when > 0, else from
// SLURM_ARRAY_TASK_COUNT or AWS_BATCH_JOB_ARRAY_SIZE. `environment` reads a
// variable (nullptr when unset). Throws invalid_input when none is set or
// the values are not a valid I/N.
ChunkChoice chunk_from_environment(int count,
                                   const std::function<const char*(const char*)>& environment);

// The index-th of `count` contiguous slices of `frames`, in order. Slices
// differ in length by at most one frame, the longer ones first; with more
// chunks than frames the last chunks are empty.
std::vector<int> chunk_of(const std::vector<int>& frames, int index, int count);

}  // namespace facet
