#include "core/host_name.hpp"

#include <unistd.h>

namespace facet {

std::string host_name() {
    char name[256] = {};
    if (::gethostname(name, sizeof name - 1) != 0) return "unknown";
    std::string host = name;
    for (char& c : host)
        if (c == '/' || c == '.') c = '_';  // the mark's separator stays unambiguous
    return host;
}

}  // namespace facet
