// The thinlayer program; all of its work is in the core library.
#include <thinlayer/app/command_line.h>

#include <iostream>

int
main(int argc, char **argv)
{
  return thinlayer::run_command_line(
    std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr);
}
