// Every class of bad scene input named by the foundation issue: the error names the
// file, the JSON path (or line) and what is wrong.

#include <boost/test/data/test_case.hpp>
#include <boost/test/unit_test.hpp>

#include <fstream>

#include "penumbra/base/input_error.h"
#include "penumbra/scene/load_scene.h"
#include "support/fixtures.h"

using namespace penumbra;
namespace data = boost::unit_test::data;

namespace {

struct BadScene {
  const char* what;      // the error class
  const char* text;      // the scene file's text
  const char* location;  // the JSON path (or "line L, column C") the error must name
  const char* message;   // a fragment the message must contain
};

std::ostream& operator<<(std::ostream& out, const BadScene& bad) {
  return out << bad.what;
}

// An object list wrapped into a version-1 scene.
#define SCENE_WITH(objects, lights) \
  "{\"penumbra\": 1, \"objects\": [" objects "], \"lights\": [" lights "]}"

const BadScene bad_scenes[] = {
    {"malformed JSON", "{\"penumbra\": 1,\n \"objects\": [}", "line 2, column 14",
     "malformed JSON"},
    {"NaN is not JSON", "{\"penumbra\": 1, \"objects\": [{\"box\": {\"min\": [NaN, 0, 0]}}]}",
     "line 1", "malformed JSON"},
    {"overflowing number",
     SCENE_WITH("{\"box\": {\"min\": [1e999, 0, 0], \"max\": [1, 1, 1]}}", ""), "",
     "number overflow parsing '1e999'"},
    {"missing version", "{\"objects\": []}", "", "missing required key \"penumbra\""},
    {"wrong version", "{\"penumbra\": 2}", "penumbra", "unsupported scene format version 2"},
    {"root not an object", "[1, 2]", "", "expected an object"},
    {"wrong type for a coordinate",
     SCENE_WITH("{\"box\": {\"min\": [0, \"a\", 0], \"max\": [1, 1, 1]}}", ""),
     "objects[0].box.min[1]", "expected a number, found string"},
    {"wrong arity of a point", SCENE_WITH("{\"box\": {\"min\": [0, 0], \"max\": [1, 1, 1]}}", ""),
     "objects[0].box.min", "array of 3 numbers"},
    {"empty box", SCENE_WITH("{\"box\": {\"min\": [0, 0, 0], \"max\": [1, 0, 1]}}", ""),
     "objects[0].box.max", "must exceed min"},
    {"object without a shape", SCENE_WITH("{\"name\": \"x\"}", ""), "objects[0]", "needs one of"},
    {"object with two shapes",
     SCENE_WITH("{\"box\": {\"min\": [0,0,0], \"max\": [1,1,1]}, \"sphere\": {\"center\": [0,0,0], "
                "\"radius\": 1}}",
                ""),
     "objects[0]", "has one shape"},
    {"convex with too few points", SCENE_WITH("{\"convex\": [[0,0,0],[1,0,0],[0,1,0]]}", ""),
     "objects[0].convex", "at least 4 points"},
    {"convex with coplanar points",
     SCENE_WITH("{\"convex\": [[0,0,0],[1,0,0],[0,1,0],[1,1,0],[2,2,0]]}", ""), "objects[0].convex",
     "4 points that are not coplanar"},
    {"non-planar polygon", SCENE_WITH("{\"polygon\": [[0,0,0],[1,0,0],[1,1,0],[0,1,0.5]]}", ""),
     "objects[0].polygon[3]", "not planar"},
    {"non-convex polygon",
     SCENE_WITH("{\"polygon\": [[0,0,0],[2,0,0],[1,1,0],[2,2,0],[0,2,0]]}", ""),
     "objects[0].polygon[", "not convex"},
    {"missing mesh file", SCENE_WITH("{\"mesh\": \"../meshes/nowhere.obj\"}", ""),
     "objects[0].mesh", "nowhere.obj: cannot open the model file"},
    {"mesh up axis", SCENE_WITH("{\"mesh\": \"../meshes/chair.obj\", \"up\": \"x\"}", ""),
     "objects[0].up", "\"z\" (the default) or \"y\""},
    {"mesh scale", SCENE_WITH("{\"mesh\": \"../meshes/chair.obj\", \"scale\": 0}", ""),
     "objects[0].scale", "greater than 0"},
    {"mesh snap", SCENE_WITH("{\"mesh\": \"../meshes/chair.obj\", \"snap\": -1}", ""),
     "objects[0].snap", ""},
    {"mesh transform size",
     SCENE_WITH("{\"mesh\": \"../meshes/chair.obj\", \"transform\": [1, 0, 0]}", ""),
     "objects[0].transform", "16 numbers"},
    {"mesh transform not affine",
     SCENE_WITH("{\"mesh\": \"../meshes/chair.obj\", \"transform\": "
                "[1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,1,1]}",
                ""),
     "objects[0].transform", "last row"},
    {"mesh transform singular",
     SCENE_WITH("{\"mesh\": \"../meshes/chair.obj\", \"transform\": "
                "[1,0,0,0, 0,1,0,0, 0,0,0,0, 0,0,0,1]}",
                ""),
     "objects[0].mesh", "chair.obj"},
    {"negative sphere radius",
     SCENE_WITH("{\"sphere\": {\"center\": [0,0,0], \"radius\": -1}}", ""),
     "objects[0].sphere.radius", "greater than 0"},
    {"duplicate object names",
     SCENE_WITH("{\"name\": \"a\", \"box\": {\"min\": [0,0,0], \"max\": [1,1,1]}}, {\"name\": "
                "\"a\", \"box\": {\"min\": [2,0,0], \"max\": [3,1,1]}}",
                ""),
     "objects[1].name", "duplicate name \"a\""},
    {"unknown material",
     SCENE_WITH("{\"box\": {\"min\": [0,0,0], \"max\": [1,1,1]}, \"material\": \"gold\"}", ""),
     "objects[0].material", "unknown material \"gold\""},
    {"reflectance out of range",
     "{\"penumbra\": 1, \"materials\": {\"m\": {\"reflectance\": 1.5}}}", "materials.m.reflectance",
     "must lie in [0, 1]"},
    {"zero-length linear source",
     SCENE_WITH("", "{\"linear\": [[1,2,3],[1,2,3]], \"candela_per_metre\": 10}"),
     "lights[0].linear", "zero length"},
    {"non-planar area source",
     SCENE_WITH("", "{\"area\": [[0,0,3],[1,0,3],[1,1,3],[0,1,3.001]], \"luminance\": 10}"),
     "lights[0].area[3]", "not planar"},
    {"non-convex area source",
     SCENE_WITH("", "{\"area\": [[0,0,3],[2,0,3],[1,0.5,3],[2,2,3],[0,2,3]], \"luminance\": 10}"),
     "lights[0].area", "convex"},
    {"collinear area source",
     SCENE_WITH("", "{\"area\": [[0,0,3],[1,0,3],[2,0,3]], \"luminance\": 10}"), "lights[0].area",
     "collinear"},
    {"repeated area vertex",
     SCENE_WITH("", "{\"area\": [[0,0,3],[1,0,3],[1,0,3],[0,1,3]], \"luminance\": 10}"),
     "lights[0].area[1]", "repeats"},
    {"area source without luminance", SCENE_WITH("", "{\"area\": [[0,0,3],[1,0,3],[0,1,3]]}"),
     "lights[0]", "exactly one of \"luminance\""},
    {"negative area luminance",
     SCENE_WITH("", "{\"area\": [[0,0,3],[1,0,3],[0,1,3]], \"luminance\": -1}"),
     "lights[0].luminance", ""},
    {"zero direction", SCENE_WITH("", "{\"directional\": [0, 0, 0], \"illuminance\": 1000}"),
     "lights[0].directional", "zero vector"},
    {"zero axis", SCENE_WITH("", "{\"point\": [0, 0, 3], \"candela\": 10, \"axis\": [0, 0, 0]}"),
     "lights[0].axis", "zero vector"},
    {"c0 along the axis",
     SCENE_WITH("",
                "{\"point\": [0, 0, 3], \"candela\": 10, \"axis\": [0, 0, -2], \"c0\": [0, 0, 1]}"),
     "lights[0].c0", "parallel to the axis"},
    {"point light without intensity", SCENE_WITH("", "{\"point\": [0, 0, 3]}"), "lights[0]",
     "exactly one of \"candela\""},
    {"negative candela", SCENE_WITH("", "{\"point\": [0, 0, 3], \"candela\": -5}"),
     "lights[0].candela", "must not be negative"},
    {"missing photometric file",
     SCENE_WITH("", "{\"point\": [0, 0, 3], \"lid\": {\"ies\": \"nowhere.ies\"}}"), "lights[0].lid",
     ""},
    {"duplicate light names",
     SCENE_WITH("",
                "{\"name\": \"l\", \"point\": [0,0,3], \"candela\": 1}, {\"name\": \"l\", "
                "\"point\": [1,0,3], \"candela\": 1}"),
     "lights[1].name", "duplicate name \"l\""},
    {"camera eye equals target",
     "{\"penumbra\": 1, \"camera\": {\"eye\": [1,1,1], \"target\": [1,1,1]}}", "camera.target",
     "must differ from the eye"},
    {"camera up along the view",
     "{\"penumbra\": 1, \"camera\": {\"eye\": [0,0,5], \"target\": [0,0,0]}}", "camera",
     "up must not be parallel"},
    {"non-integer image width",
     "{\"penumbra\": 1, \"camera\": {\"eye\": [0,5,0], \"target\": [0,0,0], \"width\": 10.5}}",
     "camera.width", "positive integer"},
};

}  // namespace

BOOST_AUTO_TEST_SUITE(scene_errors)

BOOST_DATA_TEST_CASE(bad_input_names_file_path_and_problem, data::make(bad_scenes), bad) {
  // The text is parsed as if it were fixtures/scenes/bad.json, so mesh paths resolve.
  const auto file = test::fixture("scenes/bad.json");
  try {
    parse_scene(bad.text, file);
    BOOST_ERROR("no error raised for: " << bad.what);
  } catch (const InputError& e) {
    BOOST_TEST(e.file() == file.string());
    BOOST_TEST(e.location().rfind(bad.location, 0) == 0, "location \"" << e.location() << "\"");
    BOOST_TEST(std::string(e.what()).find(bad.message) != std::string::npos,
               "message: " << e.what());
  }
}

BOOST_AUTO_TEST_CASE(a_missing_scene_file_is_named) {
  try {
    penumbra::load_scene(test::fixture("scenes/does-not-exist.json"));
    BOOST_ERROR("no error for a missing file");
  } catch (const InputError& e) {
    BOOST_TEST(e.file().find("does-not-exist.json") != std::string::npos);
    BOOST_TEST(e.message() == "cannot open the scene file: it does not exist");
  }
}

BOOST_AUTO_TEST_SUITE_END()
