#include "occlusion/core/point_cloud.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace occlusion {
namespace {

PointCloud two_station_cloud() {
  PointCloud cloud;
  cloud.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  cloud.stations = {{"scan_a", {}}, {"scan_b", {}}};
  cloud.stations[1].frame.origin = Eigen::Vector3d(5, 0, 1.5);
  cloud.station_ids = {0, 1, 1};
  cloud.intensities = {0.25f, 0.5f, 0.75f};
  return cloud;
}

TEST(PointCloudStations, StationIdsMustNameAStation) {
  PointCloud cloud = two_station_cloud();
  EXPECT_NO_THROW(cloud.validate());
  cloud.station_ids[2] = 2;
  EXPECT_THROW(cloud.validate(), std::invalid_argument);
  cloud.station_ids[2] = -1;
  EXPECT_THROW(cloud.validate(), std::invalid_argument);
  cloud.station_ids.pop_back();
  EXPECT_THROW(cloud.validate(), std::invalid_argument);
}

TEST(PointCloudStations, IntensitiesHaveOneEntryPerPoint) {
  PointCloud cloud = two_station_cloud();
  cloud.intensities.pop_back();
  EXPECT_THROW(cloud.validate(), std::invalid_argument);
}

TEST(PointCloudStations, ASubsetKeepsTheStationsAndEachPointsStation) {
  const PointCloud cloud = two_station_cloud();
  const PointCloud kept = cloud.subset({false, true, true});
  ASSERT_EQ(kept.stations.size(), 2u);
  EXPECT_EQ(kept.stations[1].name, "scan_b");
  EXPECT_EQ(kept.stations[1].frame.origin, Eigen::Vector3d(5, 0, 1.5));
  EXPECT_EQ(kept.station_ids, (std::vector<std::int32_t>{1, 1}));
  EXPECT_EQ(kept.intensities, (std::vector<float>{0.5f, 0.75f}));
  EXPECT_NO_THROW(kept.validate());
}

// A 3 x 2 frame whose pixels (0, 0), (2, 0) and (1, 1) measured a depth.
PointCloud organised_frame() {
  PointCloud cloud;
  cloud.positions = {{0, 0, 1}, {2, 0, 1}, {1, 1, 1}};
  cloud.sensor.width = 3;
  cloud.sensor.height = 2;
  cloud.pixels = {0, 2, 4};
  return cloud;
}

TEST(PointCloudPixels, EachPointHasOnePixelOfTheGrid) {
  PointCloud cloud = organised_frame();
  EXPECT_NO_THROW(cloud.validate());
  cloud.pixels[2] = 6;  // past the last pixel, 5
  EXPECT_THROW(cloud.validate(), std::invalid_argument);
  cloud.pixels[2] = 2;  // point 1's
  EXPECT_THROW(cloud.validate(), std::invalid_argument);
  cloud.pixels.pop_back();
  EXPECT_THROW(cloud.validate(), std::invalid_argument);
  cloud = organised_frame();
  cloud.sensor.height = 1;  // one row is no organised frame
  EXPECT_THROW(cloud.validate(), std::invalid_argument);
}

TEST(PointCloudPixels, ASubsetKeepsEachPointsPixel) {
  const PointCloud kept = organised_frame().subset({true, false, true});
  EXPECT_EQ(kept.pixels, (std::vector<std::uint32_t>{0, 4}));
  EXPECT_NO_THROW(kept.validate());
}

TEST(PointCloudStations, AScanStationIsTheFilesOrASingleViewSensor) {
  EXPECT_EQ(scan_stations(two_station_cloud()).size(), 2u);
  PointCloud frame;
  frame.positions = {{0, 0, 1}};
  EXPECT_TRUE(scan_stations(frame).empty());  // no pose: no station
  frame.sensor.origin = Eigen::Vector3d(1, 2, 3);
  const std::vector<Station> sensor = scan_stations(frame);
  ASSERT_EQ(sensor.size(), 1u);
  EXPECT_EQ(sensor[0].name, "sensor");
  EXPECT_EQ(sensor[0].frame.origin, Eigen::Vector3d(1, 2, 3));
  // A depth frame records its camera both ways: the station wins, once.
  frame.stations = {{"frame", frame.sensor}};
  ASSERT_EQ(scan_stations(frame).size(), 1u);
  EXPECT_EQ(scan_stations(frame)[0].name, "frame");
}

}  // namespace
}  // namespace occlusion
