#pragma once
// Work done in a child process, for libraries that are not safe against
// hostile input: assimp's readers, fuzzed, write out of bounds, abort on
// their own assertions and allocate gigabytes from a few bytes
// (docs/hardening.md). In a child, such a failure costs the child, and the
// parent reports it as an error naming the file, with the exit code a bad
// input gets.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace facet {

struct IsolationLimits {
    uint64_t memory_bytes = 0;  // address space the child may add; 0: what is available
    unsigned cpu_seconds = 120;
};

// Runs `work` in a child process (fork) under `limits` and returns the
// bytes it returned. A facet::Error thrown in the child comes back as the
// same Error (code and message). A child that dies (a signal, the memory
// or time limit) is an Error (invalid_input) "WHAT: REASON" saying how it
// ended. Without fork (it failed), `work` runs in this process.
std::vector<uint8_t> run_isolated(const std::string& what,
                                  const std::function<std::vector<uint8_t>()>& work,
                                  const IsolationLimits& limits = {});

// Plain bytes for what a child sends back: whole numbers, floats and
// strings, read back in the same order. A reader that runs past the end
// throws facet::Error (runtime_failure): the child and parent disagree.
class ByteWriter {
  public:
    void u32(uint32_t value);
    void f32(float value);
    void text(const std::string& value);
    template <typename T>
    void array(const std::vector<T>& values) {
        u32(static_cast<uint32_t>(values.size()));
        raw(values.data(), values.size() * sizeof(T));
    }
    std::vector<uint8_t> take() { return std::move(bytes_); }

  private:
    void raw(const void* data, size_t size);
    std::vector<uint8_t> bytes_;
};

// Reads `bytes`, which must outlive it.
class ByteReader {
  public:
    explicit ByteReader(const std::vector<uint8_t>& bytes) : bytes_(bytes) {}
    explicit ByteReader(std::vector<uint8_t>&&) = delete;  // a temporary would dangle
    uint32_t u32();
    float f32();
    std::string text();
    template <typename T>
    std::vector<T> array() {
        const uint32_t count = u32();
        check(uint64_t(count) * sizeof(T));
        std::vector<T> values(count);
        raw(values.data(), values.size() * sizeof(T));
        return values;
    }

  private:
    void check(uint64_t size) const;
    void raw(void* data, size_t size);
    const std::vector<uint8_t>& bytes_;
    size_t at_ = 0;
};

}  // namespace facet
