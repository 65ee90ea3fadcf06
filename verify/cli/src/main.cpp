#include <iostream>

#include "fdh/cli/cli.hpp"

int main(int argc, char** argv) {
  return fdh::verify::run_cli(std::vector<std::string>(argv + 1, argv + argc), std::cout,
                              std::cerr);
}
