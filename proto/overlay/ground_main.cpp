// PROTOTYPE timing: the pairwise arrangement on a dumped overlay input (weight px py qx qy per
// line, rationals), against CGAL::insert of the same segments (vertices, edges, faces).
#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>

#include "segment_arrangement.h"

using namespace penumbra;

int main(int argc, char** argv) {
  std::ifstream in(argv[1]);
  const bool with_cgal = argc > 2;
  std::vector<proto::LayerSegment> segments;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    long weight;
    std::string px, py, qx, qy;
    words >> weight >> px >> py >> qx >> qy;
    const auto point = [](const std::string& x, const std::string& y) {
      return point_from<Point2>(RationalPoint2(Rational(x), Rational(y)));
    };
    segments.push_back({point(px, py), point(qx, qy), weight});
  }
  std::printf("%zu segments\n", segments.size());
  const auto t0 = std::chrono::steady_clock::now();
  const proto::SegmentArrangement arrangement = proto::arrange(segments);
  const auto t1 = std::chrono::steady_clock::now();
  const auto parts = proto::polygons_by_count(arrangement, [](long c) { return c > 0 ? c : -1L; });
  const auto t2 = std::chrono::steady_clock::now();
  std::size_t polygons = 0;
  for (const auto& part : parts) polygons += part.second.size();
  const auto secs = [](auto a, auto b) { return std::chrono::duration<double>(b - a).count(); };
  std::printf("pairwise: %zu vertices, %zu edges, %zu faces; arrange %.2f s, read back %.2f s; %zu counts, %zu polygons\n",
              arrangement.points.size(), arrangement.origin.size() / 2, arrangement.faces,
              secs(t0, t1), secs(t1, t2), parts.size(), polygons);
  if (with_cgal) {
    using Traits = CGAL::Arr_segment_traits_2<Kernel>;
    CGAL::Arrangement_2<Traits> cgal;
    std::vector<Traits::Curve_2> curves;
    for (const auto& s : segments) curves.emplace_back(s.a, s.b);
    const auto t3 = std::chrono::steady_clock::now();
    CGAL::insert(cgal, curves.begin(), curves.end());
    const auto t4 = std::chrono::steady_clock::now();
    std::printf("CGAL: %zu vertices, %zu edges, %zu faces; insert %.2f s\n", cgal.number_of_vertices(),
                cgal.number_of_edges(), cgal.number_of_faces(), secs(t3, t4));
  }
  return 0;
}
