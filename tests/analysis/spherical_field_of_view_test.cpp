#include "occlusion/analysis/spherical_field_of_view.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace occlusion {
namespace {

double radians(double degrees) {
  return degrees * M_PI / 180.0;
}

// A direction in the scanner's frame (z up) at this elevation and azimuth.
Eigen::Vector3d direction(double elevation_degrees, double azimuth_degrees) {
  const double e = radians(elevation_degrees), a = radians(azimuth_degrees);
  return {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
}

// One station at (1, 2, 3), turned 90 degrees about x (the scanner's up is
// the cloud's -y), with points 4 m away on a grid of `columns` azimuths from
// 0 in 10-degree steps and 10 elevations from -30 to +60 degrees.
PointCloud station_scan(std::size_t columns) {
  PointCloud cloud;
  Station station{"north", {}};
  station.frame.origin = Eigen::Vector3d(1, 2, 3);
  station.frame.orientation =
      Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()));
  station.frame.width = columns;
  station.frame.height = 10;
  for (std::size_t c = 0; c < columns; ++c) {
    for (int r = 0; r < 10; ++r) {
      const Eigen::Vector3d d = direction(-30.0 + 10.0 * r, 10.0 * static_cast<double>(c));
      cloud.positions.push_back(
          (station.frame.origin + station.frame.orientation * (4.0 * d)).cast<float>());
    }
  }
  cloud.stations = {station};
  return cloud;
}

TEST(SphericalFieldOfView, FullTurnIsItsElevationBandWidenedByHalfARow) {
  const PointCloud cloud = station_scan(36);
  ASSERT_TRUE(is_laser_station(cloud));
  const SphericalFieldOfView view = measure_spherical_field_of_view(cloud);
  EXPECT_TRUE(view.full_turn);
  // 10 rows over 90 degrees: 10 degrees apart, half a row is 5.
  EXPECT_NEAR(view.elevation_lo_degrees(), -35.0, 1e-4);
  EXPECT_NEAR(view.elevation_hi_degrees(), 65.0, 1e-4);
  EXPECT_EQ(view.azimuth_span_degrees(), 360.0);
  const Eigen::Quaterniond& turn = cloud.stations[0].frame.orientation;
  for (const double azimuth : {0.0, 95.0, 183.0, 301.0}) {
    EXPECT_TRUE(view.contains(turn * direction(64.0, azimuth))) << azimuth;
    EXPECT_TRUE(view.contains(turn * direction(-34.0, azimuth))) << azimuth;
    EXPECT_FALSE(view.contains(turn * direction(66.0, azimuth))) << azimuth;
    EXPECT_FALSE(view.contains(turn * direction(-36.0, azimuth))) << azimuth;
  }
  // In the cloud's frame the scanner's up is -y: straight down -y is above
  // the band, and the cloud's +z is level for the scanner.
  EXPECT_FALSE(view.contains(Eigen::Vector3d(0, -1, 0)));
  EXPECT_FALSE(view.contains(Eigen::Vector3d(0, 1, 0)));
  EXPECT_TRUE(view.contains(Eigen::Vector3d(0, 0, 1)));
}

TEST(SphericalFieldOfView, PartialTurnIsItsAzimuthWindow) {
  // Ten columns, 0 to 90 degrees: a window 100 degrees wide from -5.
  const PointCloud cloud = station_scan(10);
  const SphericalFieldOfView view = measure_spherical_field_of_view(cloud);
  EXPECT_FALSE(view.full_turn);
  EXPECT_NEAR(view.azimuth_span_degrees(), 100.0, 1e-4);
  EXPECT_NEAR(view.azimuth_start * 180.0 / M_PI, 355.0, 1e-4);
  const Eigen::Quaterniond& turn = cloud.stations[0].frame.orientation;
  EXPECT_TRUE(view.contains(turn * direction(0.0, 94.0)));
  EXPECT_TRUE(view.contains(turn * direction(0.0, 357.0)));
  EXPECT_TRUE(view.contains(turn * direction(0.0, 45.0)));
  EXPECT_FALSE(view.contains(turn * direction(0.0, 96.0)));
  EXPECT_FALSE(view.contains(turn * direction(0.0, 350.0)));
  EXPECT_FALSE(view.contains(turn * direction(0.0, 200.0)));
}

TEST(SphericalFieldOfView, OnlyASingleGriddedStationIsALaserStation) {
  PointCloud cloud = station_scan(36);
  cloud.stations[0].frame.height = 0;  // no grid
  EXPECT_FALSE(is_laser_station(cloud));
  cloud = station_scan(36);
  cloud.stations.push_back(cloud.stations[0]);  // two stations
  EXPECT_FALSE(is_laser_station(cloud));
  cloud = station_scan(36);
  cloud.sensor = cloud.stations[0].frame;  // a depth frame's camera: a pinhole
  EXPECT_FALSE(is_laser_station(cloud));
  EXPECT_THROW(measure_spherical_field_of_view(cloud), std::invalid_argument);
  cloud = station_scan(36);
  cloud.positions.push_back(cloud.stations[0].frame.origin.cast<float>());
  EXPECT_THROW(measure_spherical_field_of_view(cloud), std::invalid_argument);
}

}  // namespace
}  // namespace occlusion
