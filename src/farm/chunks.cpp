#include "farm/chunks.hpp"

#include <algorithm>
#include <cstddef>

#include "core/error.hpp"
#include "core/number_text.hpp"

namespace facet {
namespace {

ChunkChoice checked(long long index, long long count, const std::string& origin) {
    const SourceLocation where{"", 0, 0, "command line " + origin};
    if (count < 1 || count > 1000000)
        fail_input(where, "", "the chunk count must be from 1 to 1000000");
    if (index < 0 || index >= count)
        fail_input(where, "",
                   "chunk " + std::to_string(index) + " of " + std::to_string(count) +
                       " does not exist: chunks are numbered from 0, so " + std::to_string(count) +
                       " chunks are 0/" + std::to_string(count) + " to " +
                       std::to_string(count - 1) + "/" + std::to_string(count));
    return {static_cast<int>(index), static_cast<int>(count), origin};
}

}  // namespace

ChunkChoice parse_chunk(const std::string& text) {
    const std::string origin = "--chunk " + text;
    const size_t slash = text.find('/');
    std::optional<long long> index, count;
    if (slash != std::string::npos) {
        index = read_whole_number(std::string_view(text).substr(0, slash));
        count = read_whole_number(std::string_view(text).substr(slash + 1));
    }
    if (!index || !count)
        fail_input({"", 0, 0, "command line " + origin}, "",
                   "expected I/N, e.g. 0/6 for the first of six chunks (numbered from 0)");
    return checked(*index, *count, origin);
}

ChunkChoice chunk_from_environment(int count,
                                   const std::function<const char*(const char*)>& environment) {
    std::string origin;
    long long index = -1, total = count;
    for (const char* name :
         {"SLURM_ARRAY_TASK_ID", "JOB_COMPLETION_INDEX", "AWS_BATCH_JOB_ARRAY_INDEX"}) {
        const char* value = environment(name);
        if (!value) continue;
        origin = "--chunk-from-env (" + std::string(name) + "=" + value;
        const std::optional<long long> number = read_whole_number(value);
        if (!number)
            fail_input({"", 0, 0, "environment " + std::string(name) + "=" + value}, "",
                       "expected a whole number (a task index from 0)");
        index = *number;
        break;
    }
    if (origin.empty())
        fail_input({"", 0, 0, "command line --chunk-from-env"}, "",
                   "none of SLURM_ARRAY_TASK_ID, JOB_COMPLETION_INDEX (Kubernetes) or "
                   "AWS_BATCH_JOB_ARRAY_INDEX is set; give --chunk I/N instead");
    if (count > 0) {
        origin += ", --chunks " + std::to_string(count);
    } else {
        for (const char* name : {"SLURM_ARRAY_TASK_COUNT", "AWS_BATCH_JOB_ARRAY_SIZE"}) {
            const char* value = environment(name);
            if (!value) continue;
            origin += ", " + std::string(name) + "=" + value;
            const std::optional<long long> number = read_whole_number(value);
            if (!number)
                fail_input({"", 0, 0, "environment " + std::string(name) + "=" + value}, "",
                           "expected a whole number of tasks");
            total = *number;
            break;
        }
        if (total <= 0)
            fail_input({"", 0, 0, "command line " + origin + ")"}, "",
                       "the number of chunks is not in the environment; give --chunks N");
    }
    return checked(index, total, origin + ")");
}

std::vector<int> chunk_of(const std::vector<int>& frames, int index, int count) {
    const size_t n = frames.size(), chunks = static_cast<size_t>(count);
    const size_t i = static_cast<size_t>(index);
    const size_t base = n / chunks, longer = n % chunks;
    const size_t start = i * base + std::min(i, longer);
    const size_t length = base + (i < longer ? 1 : 0);
    return std::vector<int>(frames.begin() + static_cast<std::ptrdiff_t>(start),
                            frames.begin() + static_cast<std::ptrdiff_t>(start + length));
}

}  // namespace facet
