// Misspelt keys get a "did you mean" hint naming the closest allowed key.
#include <catch2/catch.hpp>

#include "scene/scene_desc.hpp"
#include "scene_support.hpp"
#include "support.hpp"

using namespace facet;

namespace {

std::string error_for(const std::string& yaml) {
    test::TempDir dir("hints");
    return test::load_error(test::write_text(dir.file("scene.yaml"), yaml));
}

}  // namespace

TEST_CASE("unknown keys suggest the nearest known key", "[scene][hints]") {
    CHECK_THAT(error_for("objects:\n  - { primitive: cube, material: { shinyness: 3 } }\n"),
               Catch::Contains("did you mean 'shininess'?"));
    CHECK_THAT(error_for("camera: { fvo: 30 }\nobjects: [ { primitive: cube } ]\n"),
               Catch::Contains("did you mean 'fov'?"));
    CHECK_THAT(error_for("objets: [ { primitive: cube } ]\n"),
               Catch::Contains("did you mean 'objects'?"));
    // Nothing close: no guess, just the list.
    std::string far = error_for("camera: { magnification: 2 }\nobjects: [ { primitive: cube } ]\n");
    CHECK_THAT(far, !Catch::Contains("did you mean"));
    CHECK_THAT(far, Catch::Contains("expected one of: position, target"));
}
