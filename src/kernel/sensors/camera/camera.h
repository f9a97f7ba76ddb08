// A camera: a pinhole image of the world as it is at each sample, `width` x `height` pixels over a
// horizontal field of view `fov` (square pixels), from a mount `mount_x`, `mount_y` in the robot's
// frame and `mount_z` above the ground, looking ahead and `pitch` down. Rendered with OpenGL on
// Mesa's software rasteriser (sensors/camera/offscreen_renderer.h), in the flat colours the
// scenario gives the ground, the sky, the obstacles and the bodies: no lighting, so a frame is a
// function of the scene alone. Sampled at `rate` on the simulated clock; with `depth`, each pixel's
// distance along the optical axis too (m; +Inf where nothing is within `far`).
#pragma once

namespace sanet::sensors {

struct CameraSettings {
  int width = 320, height = 240;    // pixels
  double fov = 1.0471975511965976;  // rad, horizontal (60 degrees)
  double rate = 10;                 // Hz
  double mount_x = 0, mount_y = 0;  // m, from the reference point, robot frame
  double mount_z = 0.3;             // m, the optical centre above the ground
  double pitch = 0;                 // rad, down from level
  double near = 0.05, far = 100;    // m: what is drawn lies between
  bool depth = false;               // also a depth image (32FC1)
  double record_rate = 0;           // Hz of pictures in the record (trace.mcap), as PNG; 0: every picture
  double noise = 0;                 // levels (of 255): standard deviation of each pixel's channels
};

}  // namespace sanet::sensors
