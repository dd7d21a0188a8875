#pragma once
// `penumbra shadows SCENE --times ...`: the shadows of the scene's sun at several times,
// the shadow diagram of a sun study (docs/sun-hours.md, "Shadow diagrams").

#include <string>

#include "penumbra/scene/scene.h"
#include "penumbra/shadow/shadow_map.h"

namespace penumbra::cli {

struct DiagramArguments {
  std::string scene;
  std::string light;   // the sun (when the scene has several)
  std::string times;   // FROM,TO,STEP or T1,T2,...
  std::string output;  // the diagram JSON ("" or "-": standard output)
  std::string svg;     // the plan-view diagram
  bool exact = false;
  ShadowOptions options;  // receivers and culling as the verb's
  std::string dask;       // the scheduler to compute the times on, or ""
};

// computes and writes the diagram; returns the exit status. Throws InputError for bad
// times and for a scene without a sun given by place and time.
int run_shadow_diagram(const Scene& scene, const DiagramArguments& arguments);

}  // namespace penumbra::cli
