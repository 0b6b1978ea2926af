#include <gtest/gtest.h>

#include "occlusion/io/cloud_io.hpp"

namespace occlusion {
namespace {

TEST(CloudFileStem, DropsOnlyTheSuffixItsReaderReadsBy) {
  EXPECT_EQ(cloud_file_stem("scans/room_1.pcd"), "room_1");
  EXPECT_EQ(cloud_file_stem("scans/Room.PLY"), "Room");
  EXPECT_EQ(cloud_file_stem("frames/kitchen.frame.json"), "kitchen");
  EXPECT_EQ(cloud_file_stem("scans/site.v2.e57"), "site.v2");
}

TEST(CloudFileStem, KeepsAFolderNameWhole) {
  // The study's generated rooms: the dot is part of the name, not an extension.
  EXPECT_EQ(cloud_file_stem("rooms/genA0_s10_sp0.04"), "genA0_s10_sp0.04");
  EXPECT_EQ(cloud_file_stem("rooms/genA0_s10_sp0.04/"), "genA0_s10_sp0.04");
  EXPECT_EQ(cloud_file_stem("Area_1/office_1"), "office_1");
}

}  // namespace
}  // namespace occlusion
