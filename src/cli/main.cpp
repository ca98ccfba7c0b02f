#include <iostream>

#include "cli/cli.h"
#include "cli/command.h"

int main(int argc, char** argv) {
  std::ios::sync_with_stdio(false);
  apollonius::set_process_ends_after_command(true);
  return apollonius::run_cli(std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr);
}
