// Loads a scene through the installed library and prints its object count.
#include <iostream>

#include <penumbra/scene/load_scene.h>

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  const penumbra::Scene scene = penumbra::load_scene(argv[1]);
  std::cout << scene.objects.size() << "\n";
  return 0;
}
