#include "embree_common.hpp"

#include <stdexcept>

namespace occlusion::bench {

EmbreeTracer::EmbreeTracer(unsigned threads) {
  const std::string config = "threads=" + std::to_string(std::max(1u, threads));
  device_ = rtcNewDevice(config.c_str());
  if (!device_) throw std::runtime_error("embree: rtcNewDevice failed");
}

EmbreeTracer::~EmbreeTracer() {
  release_scene();
  rtcReleaseDevice(device_);
}

void EmbreeTracer::check(const char* what) const {
  const RTCError error = rtcGetDeviceError(device_);
  if (error != RTC_ERROR_NONE) {
    throw std::runtime_error(std::string("embree: ") + what + " failed with error " +
                             std::to_string(static_cast<int>(error)));
  }
}

void EmbreeTracer::release_scene() {
  if (scene_) {
    rtcReleaseScene(scene_);
    scene_ = nullptr;
  }
}

unsigned EmbreeTracer::attach(RTCGeometry geometry) {
  rtcCommitGeometry(geometry);
  const unsigned id = rtcAttachGeometry(scene_, geometry);
  rtcReleaseGeometry(geometry);
  check("rtcAttachGeometry");
  return id;
}

void EmbreeTracer::commit_scene() {
  rtcCommitScene(scene_);
  check("rtcCommitScene");
}

void EmbreeTracer::occluded(const Ray* rays, std::size_t count, std::uint8_t* occluded,
                            unsigned threads) const {
  occluded_made(
      count,
      [rays](std::size_t i, Ray& ray) {
        ray = rays[i];
        return true;
      },
      occluded, threads);
}

}  // namespace occlusion::bench
