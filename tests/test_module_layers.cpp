// The module graph (cmake/module_graph.txt, docs/architecture.md
// "Modules"): every `#include "module/..."` in src/ goes along an edge the
// graph lists, every listed edge is used, every folder of src/ is a module
// of the graph, and the graph has no cycle. CMake links the modules from
// the same file, so a link cannot hide an include the graph does not allow.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "support.hpp"

namespace fs = std::filesystem;

namespace {

using Graph = std::map<std::string, std::set<std::string>>;

Graph read_graph() {
    std::ifstream in(facet::test::source_dir() + "/cmake/module_graph.txt");
    REQUIRE(in);
    Graph graph;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        const size_t colon = line.find(':');
        REQUIRE(colon != std::string::npos);
        std::set<std::string>& uses = graph[line.substr(0, colon)];
        std::istringstream words(line.substr(colon + 1));
        for (std::string word; words >> word;) uses.insert(word);
    }
    return graph;
}

// Per module, the modules its files include, each with one file that does.
std::map<std::string, std::map<std::string, std::string>> read_includes() {
    const std::string src = facet::test::source_dir() + "/src";
    const std::regex include(R"re(^\s*#\s*include\s*"([a-z_]+)/)re");
    std::map<std::string, std::map<std::string, std::string>> found;
    for (const auto& entry : fs::recursive_directory_iterator(src)) {
        if (!entry.is_regular_file()) continue;
        const std::string ext = entry.path().extension().string();
        if (ext != ".cpp" && ext != ".hpp" && ext != ".h") continue;
        const std::string module = fs::relative(entry.path(), src).begin()->string();
        std::ifstream in(entry.path());
        std::smatch m;
        for (std::string line; std::getline(in, line);)
            if (std::regex_search(line, m, include) && m[1] != module &&
                fs::is_directory(src + "/" + m[1].str()))
                found[module].emplace(m[1], fs::relative(entry.path(), src).string());
    }
    return found;
}

}  // namespace

TEST_CASE("every include between modules follows cmake/module_graph.txt, which has no cycle",
          "[layers]") {
    const Graph graph = read_graph();
    const auto includes = read_includes();
    // Every folder of src/ is a module of the graph, and the reverse.
    for (const auto& entry : fs::directory_iterator(facet::test::source_dir() + "/src"))
        if (entry.is_directory()) CHECK(graph.count(entry.path().filename().string()) == 1);
    for (const auto& [module, uses] : graph) {
        INFO("module " << module);
        CHECK(fs::is_directory(facet::test::source_dir() + "/src/" + module));
        for (const std::string& used : uses) CHECK(graph.count(used) == 1);
    }
    // Every include along an edge; every edge used by some include.
    for (const auto& [module, used] : includes)
        for (const auto& [target, file] : used) {
            INFO(file << " includes " << target << "/, which " << module
                      << " may not (cmake/module_graph.txt)");
            CHECK(graph.at(module).count(target) == 1);
        }
    for (const auto& [module, uses] : graph)
        for (const std::string& used : uses) {
            INFO("cmake/module_graph.txt lets " << module << " include " << used
                                                << ", but nothing does: remove the edge");
            CHECK((includes.count(module) && includes.at(module).count(used)));
        }
    // No cycle: a depth-first walk never meets a module still on its path.
    std::map<std::string, int> state;  // 1 on the path, 2 done
    std::function<bool(const std::string&)> acyclic = [&](const std::string& m) {
        if (state[m] == 1) return false;
        if (state[m] == 2) return true;
        state[m] = 1;
        for (const std::string& used : graph.at(m))
            if (!acyclic(used)) return false;
        state[m] = 2;
        return true;
    };
    for (const auto& [module, uses] : graph) {
        INFO("a cycle through " << module);
        CHECK(acyclic(module));
    }
}
