// placeholder until the evolution engineer's implementation lands (issue 3)
#include <iostream>

#include "cambrian/error.hpp"
#include "commands.hpp"

namespace cambrian {

int runEvolve(int, char**) {
  std::cerr << "cambrian evolve: not built yet\n";
  return static_cast<int>(ExitCode::failure);
}

}  // namespace cambrian
