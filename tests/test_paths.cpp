// The paths the tests find things by. They come from CMake as compile
// definitions of this file alone, so that no other test object holds an
// absolute path: ccache then hits them from a clone in another folder.
#include "support.hpp"

namespace facet::test {

std::string source_dir() {
    return FACET_SOURCE_DIR;
}
std::string baselines_dir() {
    return FACET_BASELINES;
}
std::string facet_executable() {
    return FACET_EXECUTABLE;
}
std::string build_dir() {
    return FACET_BUILD_DIR;
}
std::string styles_dir() {
    return FACET_STYLES_DIR;
}
std::string override_scene() {
    return FACET_OVERRIDE_SCENE;
}

}  // namespace facet::test
