// Every way an OBJ file can be wrong gives an InputError that names the file
// and the line, never a crash or a quietly different mesh.

#include <gtest/gtest.h>

#include <cstddef>
#include <string>

#include "io/scratch_directory.hpp"
#include "occlusion/io/input_error.hpp"
#include "occlusion/io/obj_reader.hpp"

namespace occlusion {
namespace {

const char* const kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";  // lines 1-3

// Parses `text` as "scene.obj" and checks the error's location and wording.
void expect_error(const std::string& text, std::size_t line, const std::string& fragment) {
  try {
    parse_obj(text, "scene.obj");
    ADD_FAILURE() << "no error for:\n" << text;
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_EQ(error.path, "scene.obj");
    EXPECT_EQ(error.line, line) << message;
    const std::string prefix =
        line == 0 ? std::string("scene.obj: ") : "scene.obj:" + std::to_string(line) + ": ";
    EXPECT_EQ(message.rfind(prefix, 0), 0u) << message;
    EXPECT_NE(message.find(fragment), std::string::npos)
        << "'" << message << "' lacks '" << fragment << "'";
  }
}

TEST(ObjReaderErrors, MissingFileNamesThePath) {
  const std::string path = "/nonexistent/dir/missing.obj";
  try {
    read_obj(path);
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(error.path, path);
    EXPECT_EQ(error.line, 0u);
    EXPECT_EQ(std::string(error.what()).rfind(path + ": cannot open", 0), 0u) << error.what();
  }
}

TEST(ObjReaderErrors, DirectoryIsNotAFile) {
  testing::ScratchDirectory dir;
  try {
    read_obj(dir.path().string());
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("directory"), std::string::npos) << error.what();
  }
}

TEST(ObjReaderErrors, BadContentInAFileNamesThePathAndLine) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("broken.obj");
  testing::write_text(path, std::string(kTriangle) + "f 1 2 4\n");
  try {
    read_obj(path);
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(error.path, path);
    EXPECT_EQ(error.line, 4u);
    EXPECT_EQ(std::string(error.what()).rfind(path + ":4: ", 0), 0u) << error.what();
  }
}

TEST(ObjReaderErrors, IndexZero) {
  expect_error(std::string(kTriangle) + "f 0 1 2\n", 4, "index 0");
}

TEST(ObjReaderErrors, PositiveIndexPastTheLastVertex) {
  expect_error(std::string(kTriangle) + "f 1 2 3\n\nf 1 2 4\n", 6, "index 4 is out of range");
}

TEST(ObjReaderErrors, NegativeIndexBeforeTheFirstVertex) {
  expect_error(std::string(kTriangle) + "f -1 -2 -4\n", 4, "-4 is out of range");
}

TEST(ObjReaderErrors, NegativeIndexCountsOnlyVerticesReadSoFar) {
  // Four vertices in the file, but only three before the face.
  expect_error(std::string(kTriangle) + "f -4 -2 -1\nv 1 1 0\n", 4, "out of range");
}

TEST(ObjReaderErrors, HugeIndex) {
  expect_error(std::string(kTriangle) + "f 1 2 99999999999\n", 4, "out of range");
}

TEST(ObjReaderErrors, NonNumericCoordinate) {
  expect_error("v 0 0 0\nv 1 abc 0\n", 2, "'abc' is not a number");
}

TEST(ObjReaderErrors, NumberWithTrailingGarbage) {
  expect_error("v 0 0 0\nv 1 2 3x\n", 2, "'3x' is not a number");
}

// Text after a vertex's numbers was ignored, so statements run together on
// one line (a lone CR read as no line end) lost their vertices silently.
TEST(ObjReaderErrors, TextAfterAVertexsNumbers) {
  expect_error("v 0 0 0\nv 1 0 0 hello world\n", 2,
               "vertex has 'hello' after its coordinates, where only numbers may follow");
  expect_error("v 0 0 0 1 v 1 0 0\n", 1, "'v' after its coordinates");
  expect_error("v 0 0 0 0.5 0.5\n", 1, "vertex has 5 numbers");
  expect_error("v 0 0 0 1 2 3 4 5\n", 1, "vertex has 8 numbers");
}

TEST(ObjReaderErrors, MissingCoordinate) {
  expect_error("v 0 0 0\n\nv 1 2\n", 3, "2 coordinates, expected 3");
  expect_error("v\n", 1, "0 coordinates");
}

TEST(ObjReaderErrors, NonFiniteCoordinate) {
  expect_error("v nan 0 0\n", 1, "not finite");
  expect_error("v 0 -inf 0\n", 1, "not finite");
  expect_error("v 0 0 1e400\n", 1, "not finite");
}

TEST(ObjReaderErrors, FaceWithFewerThanThreeVertices) {
  expect_error(std::string(kTriangle) + "f 1 2\n", 4, "2 vertices, needs at least 3");
  expect_error(std::string(kTriangle) + "f\n", 4, "0 vertices");
}

TEST(ObjReaderErrors, MalformedCorner) {
  expect_error(std::string(kTriangle) + "f 1/x 2 3\n", 4, "'1/x' is not a valid reference");
  expect_error(std::string(kTriangle) + "f a b c\n", 4, "'a' is not a valid reference");
  expect_error(std::string(kTriangle) + "f 1/1/1/1 2 3\n", 4, "not a valid reference");
  expect_error(std::string(kTriangle) + "f /1 2 3\n", 4, "not a valid reference");
}

TEST(ObjReaderErrors, OnlyDegenerateFacesLeaveNoMesh) {
  expect_error(std::string(kTriangle) + "f 1 2 2\nf 3 1 -1\n", 0,
               "no faces with an area: all 2 are degenerate (first, line 4: degenerate face "
               "(zero area): vertex 2 is used twice in one triangle)");
}

TEST(ObjReaderErrors, LineNumbersCountContinuedAndCrlfLines) {
  // Lines: 1-3 vertices (CRLF), 4-5 one continued face, 6 the bad face.
  expect_error("v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 \\\r\n3\r\nf 1 2 7\r\n", 6, "out of range");
  // An error inside a continued statement names the line it starts on.
  expect_error("v 0 0 0\nv 1 \\\n x 0\n", 2, "'x' is not a number");
}

TEST(ObjReaderErrors, LineNumbersCountLoneCrLines) {
  // Lines 1-3 end in CR alone, line 4 in CR LF, line 5 in LF.
  expect_error("v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r\nf 1 2 5\n", 5, "out of range");
}

TEST(ObjReaderErrors, NoFaces) {
  expect_error("", 0, "no faces");
  expect_error(std::string(kTriangle) + "g empty\nl 1 2\n", 0, "no faces");
}

}  // namespace
}  // namespace occlusion
