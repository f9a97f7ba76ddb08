// Pictures of a Scenery (sensors/surroundings.h) through OpenGL on Mesa's OSMesa, which renders
// into memory with the llvmpipe software rasteriser: no X server, no GPU. Each renderer holds its
// own context and picture, and may be used from any thread, one thread at a time (it binds its
// context to the calling thread for each picture).
//
// Reproducible: flat colours, no lighting, no blending; llvmpipe's vector width is fixed at 128
// bits (LP_NATIVE_VECTOR_WIDTH, unless the environment sets it) so that machines whose CPUs
// differ draw the same pixels.
#pragma once

#include <cstdint>
#include <vector>

#include "physics/physics_world.h"
#include "sanet/readings.h"
#include "sensors/surroundings.h"

namespace sanet::sensors {

// Where a camera is and what it sees: its optical centre, heading (yaw, about z from x) and pitch
// (down from level), horizontal field of view, clipping planes and picture size.
struct CameraView {
  physics::Vec3 eye;
  double yaw = 0, pitch = 0;
  double fov = 1, near = 0.05, far = 100;
  int width = 1, height = 1;
};

class OffscreenRenderer {
 public:
  // Throws std::runtime_error when OSMesa cannot make a context or a picture of that size.
  OffscreenRenderer(int width, int height);
  ~OffscreenRenderer();
  OffscreenRenderer(const OffscreenRenderer&) = delete;
  OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;

  // `scenery` and `bodies` seen from `view`, leaving out node `skip`'s body: rgb8 rows top to
  // bottom into `out`, and its depth (m along the optical axis) when `depth`.
  void Render(const CameraView& view, const Scenery& scenery, const std::vector<SceneBody>& bodies, NodeId skip,
              bool depth, ImageReading& out);

 private:
  void ReadBack(const CameraView& view, bool depth, ImageReading& out);

  void* context_ = nullptr;  // OSMesaContext
  int width_, height_;
  std::vector<std::uint8_t> rgba_;  // what OSMesa draws into, bottom row first
  std::vector<float> depth_;        // the depth buffer, read back
};

}  // namespace sanet::sensors
