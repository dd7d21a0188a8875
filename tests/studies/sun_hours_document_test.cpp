// The exact sun-hours document read back (io::sun_hours_from_json, the merge of a distributed
// run): on a real model (the L-shaped courtyard mesh, whose faces are made of convex pieces)
// the result read from the exact document has the same receiving faces, counts and exact
// regions as the one computed, for every face and for a subset; a document without its exact
// keys, or of other faces, is refused naming where. The document written as it is made
// (io::write_sun_hours_json) is the tree's text, and its points, rounded ahead (across
// threads on a face of many), are the exact points' roundings.

#include <boost/test/unit_test.hpp>

#include <gmpxx.h>

#include <sstream>

#include "penumbra/base/input_error.h"
#include "penumbra/io/sun_hours_document.h"
#include "penumbra/scene/load_scene.h"
#include "penumbra/scene/object_selection.h"
#include "penumbra/studies/sun_hours_request.h"
#include "support/fixtures.h"

using namespace penumbra;

namespace {

struct Study {
  Scene scene = load_scene(test::fixture("scenes/mesh-courtyard.json"));
  studies::SunHoursPlan plan;
  explicit Study(const std::string& step = "1h") {
    studies::SunHoursRequest request;
    request.site = "51.5,-0.12";
    request.date = "2026-06-21";
    request.step = step;
    plan = studies::plan_sun_hours(scene, request);
  }
  studies::SunHoursResult run(const std::optional<std::vector<Receiver>>& receivers) const {
    studies::SunHoursOptions options;
    options.receivers = receivers;
    return studies::sun_hours(scene, plan.sun, plan.instants, plan.step, options);
  }
  nlohmann::json document(const studies::SunHoursResult& result) const {
    return io::sun_hours_json(scene, result, io::sun_hours_header(scene, plan), true);
  }
};

void check_same(const studies::SunHoursResult& read, const studies::SunHoursResult& computed) {
  BOOST_TEST_REQUIRE(read.faces.receivers.size() == computed.faces.receivers.size());
  BOOST_TEST(read.faces.mesh_faces == computed.faces.mesh_faces);
  BOOST_TEST(read.steps.size() == computed.steps.size());
  BOOST_TEST(read.step.count() == computed.step.count());
  std::size_t parts = 0;
  for (std::size_t r = 0; r < computed.hours.size(); ++r) {
    BOOST_TEST(read.faces.receivers[r].object == computed.faces.receivers[r].object);
    BOOST_TEST(read.faces.receivers[r].face == computed.faces.receivers[r].face);
    const auto& got = read.hours[r].parts;
    const auto& want = computed.hours[r].parts;
    BOOST_TEST_REQUIRE(got.size() == want.size());
    for (std::size_t k = 0; k < want.size(); ++k, ++parts) {
      BOOST_TEST(got[k].count == want[k].count);
      BOOST_TEST((got[k].region == want[k].region));  // every exact point, in order
      BOOST_TEST((got[k].region.area == want[k].region.area));
    }
  }
  BOOST_TEST(parts > computed.hours.size());  // faces cut into several parts
}

}  // namespace

BOOST_AUTO_TEST_CASE(the_exact_document_reads_back_into_the_same_result) {
  const Study study;
  const studies::SunHoursResult computed = study.run(std::nullopt);
  const nlohmann::json document = study.document(computed);
  const studies::SunHoursResult read =
      io::sun_hours_from_json(study.scene, study.plan, std::nullopt, document, "merged.json");
  check_same(read, computed);
  BOOST_TEST(study.document(read) == document);
  BOOST_TEST(io::longest_whole_hours(read) == io::longest_whole_hours(computed));

  // a subset of the faces: the model's only (the ground still casts shadows)
  const auto receivers = faces_of_objects(study.scene, select_objects(study.scene, "house*"));
  const studies::SunHoursResult some = study.run(receivers);
  check_same(io::sun_hours_from_json(study.scene, study.plan, receivers, study.document(some),
                                     "tile.json"),
             some);
}

BOOST_AUTO_TEST_CASE(a_document_that_does_not_fit_is_refused_naming_where) {
  const Study study;
  const studies::SunHoursResult computed = study.run(std::nullopt);
  const auto where = [&](const nlohmann::json& document) {
    try {
      io::sun_hours_from_json(study.scene, study.plan, std::nullopt, document, "merged.json");
    } catch (const InputError& error) {
      BOOST_TEST(error.file() == "merged.json");
      return error.location();
    }
    return std::string("accepted");
  };
  // not exact: the polygons of the first part lack their rationals
  BOOST_TEST(where(io::sun_hours_json(study.scene, computed,
                                      io::sun_hours_header(study.scene, study.plan), false)) ==
             "faces[0].hours[0].polygons[0].exact");
  nlohmann::json document = study.document(computed);
  document["faces"].erase(0);
  BOOST_TEST(where(document) == "faces");
  document = study.document(computed);
  std::swap(document["faces"][0], document["faces"][1]);
  BOOST_TEST(where(document) == "faces[0]");
  document = study.document(computed);
  document["faces"][0]["hours"][0]["minutes"] = 61.5;
  BOOST_TEST(where(document) == "faces[0].hours[0].minutes");
  document = study.document(computed);
  document["faces"][0]["hours"][0]["polygons"][0]["exact"]["outer"][0][0] = "1/2x";
  BOOST_TEST(where(document) == "faces[0].hours[0].polygons[0].exact.outer");
}

BOOST_AUTO_TEST_CASE(the_document_written_as_it_is_made_is_the_formatted_tree) {
  // At 10-minute steps the courtyard's ground lists more than 256 points, so that the
  // writer computes their world doubles ahead across threads.
  const Study study("10min");
  const studies::SunHoursResult result = study.run(std::nullopt);
  std::size_t most = 0;
  for (const studies::FaceSunHours& face : result.hours) {
    std::size_t listed = 0;
    for (const Coverage& part : face.parts)
      for (const Polygon2& polygon : part.region.polygons) {
        listed += polygon.outer.size();
        for (const Ring2& hole : polygon.holes) listed += hole.size();
      }
    most = std::max(most, listed);
  }
  BOOST_TEST_REQUIRE(most > 256u);
  const io::SunHoursHeader header = io::sun_hours_header(study.scene, study.plan);
  for (const bool exact : {false, true}) {
    std::ostringstream written;
    io::write_sun_hours_json(written, study.scene, result, header, exact);
    BOOST_TEST(written.str() ==
               io::format_json(io::sun_hours_json(study.scene, result, header, exact)));
  }

  // Every printed coordinate is its exact value (the "exact" rationals, which are converted
  // one by one) rounded toward zero, as the document's doubles are.
  const nlohmann::json document = nlohmann::json::parse([&] {
    std::ostringstream written;
    io::write_sun_hours_json(written, study.scene, result, header, true);
    return written.str();
  }());
  std::size_t compared = 0;
  for (const nlohmann::json& face : document.at("faces"))
    for (const nlohmann::json& part : face.at("hours"))
      for (const nlohmann::json& polygon : part.at("polygons")) {
        const nlohmann::json& printed = polygon.at("outer");
        const nlohmann::json& rational = polygon.at("exact").at("outer");
        BOOST_TEST_REQUIRE(printed.size() == rational.size());
        for (std::size_t k = 0; k < printed.size(); ++k)
          for (std::size_t i = 0; i < 3; ++i, ++compared) {
            mpq_class x(rational[k][i].get<std::string>());
            x.canonicalize();
            BOOST_TEST(printed[k][i].get<double>() == x.get_d() + 0.0);
          }
      }
  BOOST_TEST(compared > 3 * 256u);
}
