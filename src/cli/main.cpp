#include "cli/commands.hpp"

int main(int argc, char** argv) {
    return facet::run_command_line(argc, argv);
}
