// Sun-hours (studies/sun_hours.h) against what the test derives on its own: at random
// points of every face, the duration read from the exact parts equals the number of
// sun-up steps at which the exact shadow oracle of tests/shadow/oracle.h (written apart
// from the engine) sees the sun from the point; a courtyard's lit area per step derived by
// hand; a pole on the equator at the equinox; the polar day and the polar night.

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <random>
#include <sstream>

#include "penumbra/studies/sun_hours.h"
#include "shadow/oracle.h"
#include "shadow/shadow_support.h"

using namespace penumbra;
using namespace penumbra::test;

namespace {

// the steps of one local day (offset 0) at step, as `penumbra sun-hours --date` takes them.
std::vector<sun::UtcInstant> day_steps(const std::string& date, const std::string& step) {
  const sun::UtcInstant midnight = sun::local_midnight(sun::parse_date(date), 0);
  return sun::step_instants({midnight, 0}, midnight + std::chrono::hours(24) - sun::Duration(1),
                            sun::parse_step(step));
}

// a scene of objects (JSON) under a sun at latitude and longitude.
Scene sun_scene(const std::string& objects, double latitude, double longitude,
                const std::string& time) {
  std::ostringstream text;
  text << R"({"penumbra": 1, "objects": [)" << objects
       << R"(], "lights": [{"name": "sun", "illuminance": 100000, "sun": {"latitude": )" << latitude
       << R"(, "longitude": )" << longitude << R"(, "time": ")" << time << R"("}}]})";
  return scene_from_text(text.str());
}

std::string box(const std::string& name, std::array<int, 3> min, std::array<int, 3> max) {
  std::ostringstream text;
  text << R"({"name": ")" << name << R"(", "box": {"min": [)" << min[0] << ", " << min[1] << ", "
       << min[2] << "], \"max\": [" << max[0] << ", " << max[1] << ", " << max[2] << "]}}";
  return text.str();
}

studies::SunHoursResult hours_of(const Scene& scene, const std::string& date,
                                 const std::string& step, bool parallel = true) {
  studies::SunHoursOptions options;
  options.parallel = parallel;
  return studies::sun_hours(scene, scene.suns.front(), day_steps(date, step), sun::parse_step(step),
                            options);
}

const Face& face_of(const Scene& scene, const studies::SunHoursResult& result, std::size_t r) {
  const Receiver& receiver = result.faces.receivers[r];
  return scene.objects[receiver.object].solid.faces()[receiver.face];
}

// the world area of a region of face (frame area times |u| |v|), in doubles.
double world_area(const Face& face, const Exact& area) {
  return CGAL::to_double(area) *
         std::sqrt(CGAL::to_double(face.frame.squared_u() * face.frame.squared_v()));
}

// A courtyard floor [0, w]^2 at z = 0 walled all round to height h by walls t thick.
std::string courtyard(int w, int h, int t) {
  return box("floor", {0, 0, -1}, {w, w, 0}) + ", " + box("west", {-t, -t, -1}, {0, w + t, h}) +
         ", " + box("east", {w, -t, -1}, {w + t, w + t, h}) + ", " +
         box("south", {0, -t, -1}, {w, 0, h}) + ", " + box("north", {0, w, -1}, {w, w + t, h});
}

// For each sun-up step, (a, b) = h (s_x, s_y) / s_z with s the direction toward the sun: the
// shift from a floor point to where its ray toward the sun reaches the height h.
std::vector<std::pair<Exact, Exact>> shifts_at(const studies::SunHoursResult& result, int h) {
  std::vector<std::pair<Exact, Exact>> shifts;
  for (const studies::SunStep& step : result.steps) {
    if (!step.up()) continue;
    const Vector3 s = -to_exact_vector(step.direction);
    shifts.emplace_back(h * s.x() / s.z(), h * s.y() / s.z());
  }
  return shifts;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(sun_hours)

BOOST_AUTO_TEST_CASE(durations_at_random_points_agree_with_the_oracle_step_by_step) {
  // Random boxes on a ground, on a coarse grid so that touching and coplanar faces are
  // frequent; two places and dates; hourly and half-hourly steps.
  struct Case {
    unsigned seed;
    double latitude, longitude;
    std::string date, step;
  };
  std::size_t compared = 0, mismatches = 0;
  for (const Case& c :
       {Case{1, 51.5, -0.12, "2026-03-21", "1h"}, Case{2, 40.4, -3.7, "2026-06-21", "30min"},
        Case{3, -33.9, 151.2, "2026-06-21", "1h"}}) {
    std::mt19937 random(c.seed);
    std::uniform_int_distribution<int> corner(-8, 6), size(1, 4), height(1, 8);
    std::string objects = box("ground", {-12, -12, -1}, {12, 12, 0});
    for (int k = 0; k < 6; ++k) {
      const int x = corner(random), y = corner(random);
      objects += ", " + box("b" + std::to_string(k), {x, y, 0},
                            {x + size(random), y + size(random), height(random)});
    }
    const Scene scene = sun_scene(objects, c.latitude, c.longitude, c.date + "T12:00:00+00:00");
    const studies::SunHoursResult result = hours_of(scene, c.date, c.step);
    BOOST_TEST(result.steps_up() > 0u);
    // Serial and parallel runs give the same parts.
    const studies::SunHoursResult serial = hours_of(scene, c.date, c.step, false);
    for (std::size_t r = 0; r < result.hours.size(); ++r) {
      BOOST_TEST_REQUIRE(serial.hours[r].parts.size() == result.hours[r].parts.size());
      for (std::size_t k = 0; k < result.hours[r].parts.size(); ++k)
        BOOST_TEST((serial.hours[r].parts[k].region == result.hours[r].parts[k].region));
    }

    for (std::size_t r = 0; r < result.faces.receivers.size(); ++r) {
      const Face& face = face_of(scene, result, r);
      const Ring2 ring = face_ring(face);
      // The parts tile the face.
      Exact total = 0;
      for (const Coverage& part : result.hours[r].parts) total += part.region.area;
      BOOST_TEST((total == face.area));
      for (int s = 0; s < 12; ++s) {
        const Point2 p = random_point(ring, random);
        std::size_t holding = 0, count = 0;
        bool on_boundary = false;
        for (const Coverage& part : result.hours[r].parts) {
          const Where where = locate(part.region, p);
          on_boundary = on_boundary || where == Where::boundary;
          if (where == Where::inside) ++holding, count = part.count;
        }
        if (on_boundary) continue;
        BOOST_TEST(holding == 1u);
        std::size_t seen = 0;
        for (const studies::SunStep& step : result.steps) {
          if (!step.up()) continue;
          const Light light{"sun", DirectionalLight{step.direction, 100000}, "lights[0]"};
          seen += !oracle_in_shadow(scene, face, face.frame.to_world(p), light);
        }
        ++compared;
        if (seen != count) {
          ++mismatches;
          BOOST_TEST_MESSAGE("seed " << c.seed << " "
                                     << scene.objects[result.faces.receivers[r].object].name
                                     << " face " << result.faces.receivers[r].face << ": parts say "
                                     << count << " steps, the oracle " << seen);
        }
      }
    }
  }
  BOOST_TEST(mismatches == 0u);
  BOOST_TEST(compared > 500u);
}

BOOST_AUTO_TEST_CASE(a_courtyard_gets_the_sun_derived_by_hand) {
  // A courtyard floor [0, w]^2 at z = 0 walled all round to height h (walls thick enough
  // that the sky is seen only through the opening). At a step whose sunward direction is
  // s (s_z > 0), the floor point (x, y) sees the sun exactly when the ray reaches z = h
  // inside the opening: (x + a, y + b) in [0, w]^2 with a = h s_x / s_z, b = h s_y / s_z.
  // The lit set is the rectangle [max(0, -a), min(w, w - a)] x [max(0, -b), min(w, w - b)],
  // of area (w - |a|)+ (w - |b|)+; the part lit at every step is the intersection of them.
  const int w = 10, h = 6, t = 2;
  const std::string objects = courtyard(w, h, t);
  const Scene scene = sun_scene(objects, 40.4, -3.7, "2026-06-21T12:00:00+02:00");
  const studies::SunHoursResult result = hours_of(scene, "2026-06-21", "20min");

  Exact integral = 0;  // sum over the sun-up steps of the lit area (m^2 steps)
  Exact x0 = 0, x1 = w, y0 = 0, y1 = w;
  const auto shifts = shifts_at(result, h);
  const std::size_t up = shifts.size();
  for (const auto& [a, b] : shifts) {
    const Exact dx = w - CGAL::abs(a), dy = w - CGAL::abs(b);
    if (dx > 0 && dy > 0) integral += dx * dy;
    x0 = CGAL::max(x0, -a), x1 = CGAL::min(x1, w - a);
    y0 = CGAL::max(y0, -b), y1 = CGAL::min(y1, w - b);
  }
  const Exact always = x1 > x0 && y1 > y0 ? (x1 - x0) * (y1 - y0) : Exact(0);

  std::size_t floor = result.faces.receivers.size();
  for (std::size_t r = 0; r < result.faces.receivers.size(); ++r)
    if (scene.objects[result.faces.receivers[r].object].name == "floor" &&
        face_of(scene, result, r).plane.c() > 0)
      floor = r;
  BOOST_TEST_REQUIRE(floor < result.faces.receivers.size());
  const Face& face = face_of(scene, result, floor);
  double from_parts = 0, always_from_parts = 0;
  for (const Coverage& part : result.hours[floor].parts) {
    from_parts += static_cast<double>(part.count) * world_area(face, part.region.area);
    if (part.count == up) always_from_parts = world_area(face, part.region.area);
  }
  BOOST_TEST(up > 30u);
  BOOST_TEST(CGAL::to_double(integral) > 100.0);
  BOOST_TEST(from_parts == CGAL::to_double(integral), boost::test_tools::tolerance(1e-12));
  BOOST_TEST(always_from_parts == CGAL::to_double(always), boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(a_plan_region_takes_its_share_of_the_courtyard_and_a_roof) {
  // The courtyard of the previous case; at each step the lit part of the floor is the
  // rectangle [max(0, -a), min(w, w - a)] x [max(0, -b), min(w, w - b)] derived there. A plan
  // region over the western half [-1, w/2] x [-1, w + 1] (reaching over the walls' feet,
  // which it must ignore) holds w/2 x w of the floor, and the sum over the steps of the lit
  // area inside it, derived from those rectangles cut at x = w/2, equals the sum over
  // thresholds k = 1 .. up steps of the area with at least k steps of sun inside it (each
  // part counted once per step it is lit). The walls' tops (facing up) take their own
  // shares: the region's area is the plan area of what faces up inside it.
  const int w = 10, h = 6, t = 2;
  const std::string objects =
      courtyard(w, h, t) +
      R"(, {"name": "roof", "convex": [[20, 0, 0], [30, 0, 0], [20, 10, 0], [30, 10, 0],
                                       [20, 0, 5], [30, 0, 5], [20, 5, 10], [30, 5, 10]]})";
  const Scene scene = sun_scene(objects, 40.4, -3.7, "2026-06-21T12:00:00+02:00");
  const studies::SunHoursResult result = hours_of(scene, "2026-06-21", "20min");
  const Exact half = Exact(w) / 2;
  Exact integral = 0;  // sum over the sun-up steps of the lit area west of x = w/2
  const auto shifts = shifts_at(result, h);
  const std::size_t up = shifts.size();
  for (const auto& [a, b] : shifts) {
    const Exact dx = CGAL::min(half, w - a) - CGAL::max(Exact(0), -a);
    const Exact dy = CGAL::min(Exact(w), w - b) - CGAL::max(Exact(0), -b);
    if (dx > 0 && dy > 0) integral += dx * dy;
  }
  const std::vector<Point2> west_half{{-1, -1}, {half, -1}, {half, w + 1}, {-1, w + 1}};
  const auto floor_share = [&](sun::Duration threshold) {
    for (const studies::RegionShare& share :
         studies::plan_region_shares(scene, result, west_half, threshold))
      if (scene.objects[result.faces.receivers[share.receiver].object].name == "floor")
        return share;
    return studies::RegionShare{result.faces.receivers.size(), -1, -1};
  };
  double from_shares = 0;
  for (std::size_t k = 1; k <= up; ++k)
    from_shares += world_area(face_of(scene, result, floor_share(result.step * k).receiver),
                              floor_share(result.step * k).reached);
  const auto tolerance = boost::test_tools::tolerance(1e-12);
  BOOST_TEST(CGAL::to_double(integral) > 50.0);
  BOOST_TEST(from_shares == CGAL::to_double(integral), tolerance);
  const studies::RegionShare all = floor_share(sun::Duration(0));
  BOOST_TEST_REQUIRE(all.receiver < result.faces.receivers.size());
  BOOST_TEST(
      world_area(face_of(scene, result, all.receiver), all.area) == CGAL::to_double(half * w),
      tolerance);
  BOOST_TEST(all.reached == all.area);
  // The tops inside [-1, w/2] x [-1, w + 1]: west 1 x (w + 2), south and north each
  // w/2 x 1; the east wall lies outside.
  double tops = 0;
  for (const studies::RegionShare& share :
       studies::plan_region_shares(scene, result, west_half, sun::Duration(0))) {
    const Face& face = face_of(scene, result, share.receiver);
    BOOST_TEST(CGAL::is_positive(face.plane.c()));
    if (scene.objects[result.faces.receivers[share.receiver].object].name != "floor")
      tops += world_area(face, share.area);
  }
  BOOST_TEST(tops == CGAL::to_double(Exact(w + 2) + 2 * half), tolerance);

  // The roof's slopes rise 5 over 5: over the plan square [22, 28] x [1, 4] (on the south
  // slope only) the sloped area is the plan area times sqrt(2), in world units.
  const std::vector<Point2> on_slope{{22, 1}, {28, 1}, {28, 4}, {22, 4}};
  const auto shares = studies::plan_region_shares(scene, result, on_slope, sun::Duration(0));
  BOOST_TEST_REQUIRE(shares.size() == 1u);
  const Face& slope = face_of(scene, result, shares[0].receiver);
  BOOST_TEST(world_area(slope, shares[0].area) == 18 * std::sqrt(2.0),
             boost::test_tools::tolerance(1e-12));
  BOOST_TEST(shares[0].reached == shares[0].area);  // threshold 0: all of it
  // A polygon beside everything meets nothing.
  BOOST_TEST(
      studies::plan_region_shares(scene, result, {{50, 50}, {51, 50}, {51, 51}}, sun::Duration(0))
          .empty());
}

BOOST_AUTO_TEST_CASE(a_pole_on_the_equator_at_the_equinox_sees_the_sun_east_then_west) {
  // At the equator near the equinox the sun rises due east, passes nearly overhead and
  // sets due west: the pole's east face is lit whole at every sun-up step whose light
  // travels west (d_x < 0), the west face at every other; morning and afternoon differ by
  // the equation of time (about 7 minutes on 20 March), within one 10-minute step each way.
  const std::string objects =
      box("ground", {-20, -20, -1}, {20, 20, 0}) + ", " + box("pole", {-1, -1, 0}, {1, 1, 10});
  const Scene scene = sun_scene(objects, 0, 0, "2026-03-20T12:00:00+00:00");
  const studies::SunHoursResult result = hours_of(scene, "2026-03-20", "10min");
  std::size_t west_going = 0, east_going = 0, north_going = 0, south_going = 0;
  for (const studies::SunStep& step : result.steps) {
    if (!step.up()) continue;
    west_going += step.direction[0] < 0;
    east_going += step.direction[0] > 0;
    north_going += step.direction[1] > 0;
    south_going += step.direction[1] < 0;
  }
  BOOST_TEST(west_going + east_going == result.steps_up());
  BOOST_TEST(std::abs(static_cast<long>(west_going) - static_cast<long>(east_going)) <= 2);
  BOOST_TEST(result.steps_up() >= 72u);
  BOOST_TEST(result.steps_up() <= 74u);  // 12 h 7 min of day at the equator
  for (std::size_t r = 0; r < result.faces.receivers.size(); ++r) {
    if (scene.objects[result.faces.receivers[r].object].name != "pole") continue;
    const Face& face = face_of(scene, result, r);
    const auto& parts = result.hours[r].parts;
    BOOST_TEST_REQUIRE(parts.size() == 1u);  // no other object shades the pole
    const Vector3 n = face.plane.orthogonal_vector();
    const std::size_t expected = n.z() > 0   ? result.steps_up()
                                 : n.z() < 0 ? 0
                                 : n.x() > 0 ? west_going
                                 : n.x() < 0 ? east_going
                                 : n.y() > 0 ? south_going
                                             : north_going;
    BOOST_TEST(parts.front().count == expected);
  }
}

BOOST_AUTO_TEST_CASE(the_polar_day_lights_a_roof_all_day_and_the_polar_night_never) {
  const std::string objects = box("house", {0, 0, 0}, {8, 6, 5});
  const Scene summer = sun_scene(objects, 80, 15, "2026-06-21T12:00:00+01:00");
  const studies::SunHoursResult day = hours_of(summer, "2026-06-21", "10min");
  BOOST_TEST(day.steps.size() == 144u);
  BOOST_TEST(day.steps_up() == 144u);
  const Scene winter = sun_scene(objects, 80, 15, "2026-12-21T12:00:00+01:00");
  const studies::SunHoursResult night = hours_of(winter, "2026-12-21", "10min");
  BOOST_TEST(night.steps_up() == 0u);
  for (std::size_t r = 0; r < day.faces.receivers.size(); ++r) {
    const Face& face = face_of(summer, day, r);
    BOOST_TEST_REQUIRE(day.hours[r].parts.size() == 1u);
    BOOST_TEST_REQUIRE(night.hours[r].parts.size() == 1u);
    BOOST_TEST(night.hours[r].parts.front().count == 0u);
    if (face.plane.c() > 0) {
      BOOST_TEST(day.hours[r].parts.front().count == 144u);
      BOOST_TEST(day.minutes(day.hours[r].parts.front().count) == 1440.0);
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()
