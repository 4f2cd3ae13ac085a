#include <malloc.h>

#include "cli/commands.hpp"

int main(int argc, char** argv) {
    // Frames are encoded into buffers of several megabytes, a few per frame.
    // glibc would hand those back to the kernel and fault in fresh, zeroed
    // pages for the next frame; kept in the heap they are reused.
    mallopt(M_MMAP_THRESHOLD, 256 << 20);
    mallopt(M_TRIM_THRESHOLD, 512 << 20);
    return facet::run_command_line(argc, argv);
}
