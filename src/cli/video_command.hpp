#pragma once
// `facet video OUTDIR MOVIE` and `render --video MOVIE`: a movie of a run's
// colour frames, found through its manifest (docs/video.md).
#include <string>
#include <vector>

namespace facet {

struct VideoArgs {
    std::string output_dir;  // holds manifest.json
    std::string movie;       // .mp4, .webm or .gif
    std::string camera;      // needed when the run has several cameras
    double fps = 0;          // 0: the scene's
    bool quiet = false;
    std::vector<int> frames;  // only these frames (render --video); empty: all the run has
    bool spacing_reported =
        false;  // render --video said so before rendering (uneven_frames_warning)
};

// The warning for a movie of frames that are not evenly spaced (it plays
// them at equal intervals), or "" when they are.
std::string uneven_frames_warning(const std::vector<int>& frames);

// Checks the movie's name (its format) before any work: exit code 2.
void check_movie_name(const std::string& movie);

int video_command(const VideoArgs& args);

}  // namespace facet
