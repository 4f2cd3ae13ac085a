#pragma once
// Text generated from the command line's own definition, so it cannot
// drift from it: a bash completion script and a man page (roff).
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace facet {

// `facet completion bash`: subcommands, each one's options, and the
// preset names after --style/--styles.
std::string bash_completion(const CLI::App& app, const std::vector<std::string>& styles);

// `facet man`: facet(1), from each subcommand's description and options.
std::string man_page(const CLI::App& app, const std::string& version);

}  // namespace facet
