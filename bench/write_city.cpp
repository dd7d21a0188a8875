// Writes the benchmarks' generated city (city_scene.h) as a scene file, so that the whole
// commands can be timed on the very scenes the benchmarks parse (docs/performance.md):
//   build/bench/penumbra_write_city 1000 > city1000.json

#include <cstdlib>
#include <iostream>
#include <string>

#include "city_scene.h"

int main(int argc, char** argv) {
  char* end = nullptr;
  const long count = argc == 2 ? std::strtol(argv[1], &end, 10) : 0;
  if (argc != 2 || *end != '\0' || count < 2 || count > 10000000) {
    std::cerr << "usage: penumbra_write_city N   (N polyhedra, 2 to 10000000; the scene on "
                 "standard output)\n";
    return 2;
  }
  std::cout << penumbra::bench::city_scene_json(static_cast<int>(count)) << '\n';
  return std::cout ? 0 : 1;
}
