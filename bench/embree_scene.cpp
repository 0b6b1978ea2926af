#include "embree_scene.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

namespace occlusion::bench {

namespace {

// Small enough to balance rays of uneven cost, large enough that the shared
// counter is rarely contended.
constexpr std::size_t kChunk = 4096;

}  // namespace

EmbreeScene::EmbreeScene(unsigned threads) {
  const std::string config = "threads=" + std::to_string(std::max(1u, threads));
  device_ = rtcNewDevice(config.c_str());
  if (!device_) throw std::runtime_error("embree: rtcNewDevice failed");
}

EmbreeScene::~EmbreeScene() {
  if (scene_) rtcReleaseScene(scene_);
  rtcReleaseDevice(device_);
}

void EmbreeScene::check(const char* what) const {
  const RTCError error = rtcGetDeviceError(device_);
  if (error != RTC_ERROR_NONE) {
    throw std::runtime_error(std::string("embree: ") + what + " failed with error " +
                             std::to_string(static_cast<int>(error)));
  }
}

double EmbreeScene::build(const TriangleMesh& mesh) {
  if (scene_) {
    rtcReleaseScene(scene_);
    scene_ = nullptr;
  }
  const auto start = std::chrono::steady_clock::now();
  scene_ = rtcNewScene(device_);
  RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                               RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                               mesh.vertices.size()));
  auto* indices = static_cast<std::uint32_t*>(
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                              3 * sizeof(std::uint32_t), mesh.faces.size()));
  check("rtcSetNewGeometryBuffer");
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    for (int k = 0; k < 3; ++k) vertices[3 * i + k] = static_cast<float>(mesh.vertices[i][k]);
  }
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    std::copy(mesh.faces[f].begin(), mesh.faces[f].end(), indices + 3 * f);
  }
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene_, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(scene_);
  check("rtcCommitScene");
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void EmbreeScene::occluded(const Ray* rays, std::size_t count, std::uint8_t* occluded,
                           unsigned threads) const {
  if (!scene_) throw std::logic_error("EmbreeScene::occluded before build");
  std::atomic<std::size_t> next{0};
  const auto work = [&] {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (std::size_t begin; (begin = next.fetch_add(kChunk)) < count;) {
      const std::size_t end = std::min(count, begin + kChunk);
      for (std::size_t i = begin; i < end; ++i) {
        const Ray& in = rays[i];
        RTCRay ray;
        ray.org_x = in.origin.x();
        ray.org_y = in.origin.y();
        ray.org_z = in.origin.z();
        ray.tnear = in.t_min;
        ray.dir_x = in.direction.x();
        ray.dir_y = in.direction.y();
        ray.dir_z = in.direction.z();
        ray.time = 0.0f;
        ray.tfar = in.t_max;
        ray.mask = ~0u;
        ray.id = 0;
        ray.flags = 0;
        rtcOccluded1(scene_, &context, &ray);
        // Embree marks an occluded ray by setting tfar to -infinity.
        occluded[i] = ray.tfar < 0.0f ? 1 : 0;
      }
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < std::max(1u, threads); ++t) pool.emplace_back(work);
  for (std::thread& thread : pool) thread.join();
}

}  // namespace occlusion::bench
