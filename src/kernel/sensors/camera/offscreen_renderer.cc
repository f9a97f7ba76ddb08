// The camera's pictures through OSMesa's fixed-function OpenGL (sensors/camera/offscreen_renderer.h).
#include "sensors/camera/offscreen_renderer.h"

#include <GL/osmesa.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>

namespace sanet::sensors {
namespace {

constexpr int kCylinderSides = 32;

void Color(Rgb c) { glColor3ub(c.r, c.g, c.b); }

// The six faces of a box of `size` about `center`, turned by `yaw`.
void DrawBox(physics::Vec3 center, physics::Vec3 size, double yaw) {
  const double c = std::cos(yaw), s = std::sin(yaw);
  double corner[8][3];
  for (int i = 0; i < 8; ++i) {
    const double u = (i & 1 ? 0.5 : -0.5) * size.x, v = (i & 2 ? 0.5 : -0.5) * size.y;
    corner[i][0] = center.x + c * u - s * v, corner[i][1] = center.y + s * u + c * v;
    corner[i][2] = center.z + (i & 4 ? 0.5 : -0.5) * size.z;
  }
  static const int kFaces[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
  glBegin(GL_QUADS);
  for (const auto& face : kFaces)
    for (int i : face) glVertex3dv(corner[i]);
  glEnd();
}

void DrawCylinder(Vec2 center, double radius, double bottom, double top) {
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i <= kCylinderSides; ++i) {
    const double a = 2 * M_PI * i / kCylinderSides;
    const double x = center.x + radius * std::cos(a), y = center.y + radius * std::sin(a);
    glVertex3d(x, y, bottom), glVertex3d(x, y, top);
  }
  glEnd();
  for (const double z : {bottom, top}) {
    glBegin(GL_POLYGON);
    for (int i = 0; i < kCylinderSides; ++i) {
      const double a = 2 * M_PI * i / kCylinderSides;
      glVertex3d(center.x + radius * std::cos(a), center.y + radius * std::sin(a), z);
    }
    glEnd();
  }
}

void DrawBody(const SceneBody& b) {
  Color(b.color);
  const double bottom = b.base, top = b.base + b.height;
  if (b.box)
    DrawBox({b.pose.x, b.pose.y, (bottom + top) / 2}, {b.length, b.width, b.height}, b.pose.theta);
  else
    DrawCylinder({b.pose.x, b.pose.y}, b.radius, bottom, top);
}

// The camera's projection (a frustum over the field of view, square pixels) and its view: eye
// coordinates look down -z with y up, the camera's forward and up turned by yaw and pitch.
void LoadCamera(const CameraView& v) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  const double right = v.near * std::tan(v.fov / 2), top = right * v.height / v.width;
  glFrustum(-right, right, -top, top, v.near, v.far);
  const double cy = std::cos(v.yaw), sy = std::sin(v.yaw), cp = std::cos(v.pitch), sp = std::sin(v.pitch);
  const double f[3] = {cy * cp, sy * cp, -sp}, u[3] = {cy * sp, sy * sp, cp};
  const double s[3] = {f[1] * u[2] - f[2] * u[1], f[2] * u[0] - f[0] * u[2], f[0] * u[1] - f[1] * u[0]};
  const double e[3] = {v.eye.x, v.eye.y, v.eye.z};
  const auto dot = [&e](const double* a) { return a[0] * e[0] + a[1] * e[1] + a[2] * e[2]; };
  const double m[16] = {s[0], u[0], -f[0], 0, s[1], u[1], -f[1], 0, s[2], u[2], -f[2], 0, -dot(s), -dot(u), dot(f), 1};
  glMatrixMode(GL_MODELVIEW);
  glLoadMatrixd(m);
}

}  // namespace

OffscreenRenderer::OffscreenRenderer(int width, int height)
    : width_(width), height_(height), rgba_(static_cast<std::size_t>(width) * height * 4) {
  static std::once_flag vector_width;  // before llvmpipe starts: the same pixels everywhere
  std::call_once(vector_width, [] { setenv("LP_NATIVE_VECTOR_WIDTH", "128", /*overwrite=*/0); });
  context_ = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  if (!context_) throw std::runtime_error("OSMesa could not make an OpenGL context (Mesa's libOSMesa)");
}

OffscreenRenderer::~OffscreenRenderer() { OSMesaDestroyContext(static_cast<OSMesaContext>(context_)); }

void OffscreenRenderer::Render(const CameraView& view, const Scenery& scenery, const std::vector<SceneBody>& bodies,
                               NodeId skip, bool depth, ImageReading& out) {
  if (!OSMesaMakeCurrent(static_cast<OSMesaContext>(context_), rgba_.data(), GL_UNSIGNED_BYTE, width_, height_))
    throw std::runtime_error("OSMesa could not draw a picture of " + std::to_string(width_) + " x " +
                             std::to_string(height_) + " pixels");
  glViewport(0, 0, width_, height_);
  glDisable(GL_LIGHTING), glDisable(GL_DITHER), glDisable(GL_BLEND), glShadeModel(GL_FLAT);
  glEnable(GL_DEPTH_TEST);
  glClearColor(scenery.sky.r / 255.0f, scenery.sky.g / 255.0f, scenery.sky.b / 255.0f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  LoadCamera(view);
  // The ground, as far as the camera sees: the far plane's corners lie this far from the eye.
  const double across = std::tan(view.fov / 2), up = across * view.height / view.width;
  const double reach = view.far * std::sqrt(1 + across * across + up * up);
  Color(scenery.ground);
  glBegin(GL_QUADS);
  for (const auto& [dx, dy] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}})
    glVertex3d(view.eye.x + dx * reach, view.eye.y + dy * reach, 0);
  glEnd();
  for (const SceneBox& b : scenery.boxes) {
    Color(b.color);
    DrawBox(b.center, b.size, b.yaw);
  }
  for (const SceneBody& b : bodies)
    if (b.node != skip) DrawBody(b);
  glFinish();
  ReadBack(view, depth, out);
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);  // free to be made current on another thread
}

// OSMesa's rows run bottom to top, an image's top to bottom. Depth from the buffer's [0, 1] to
// metres along the axis: z = 2 f n / (f + n - (2 d - 1)(f - n)); the far plane's 1 is +Inf.
void OffscreenRenderer::ReadBack(const CameraView& view, bool depth, ImageReading& out) {
  out.width = width_, out.height = height_, out.encoding = "rgb8";
  out.data.resize(static_cast<std::size_t>(width_) * height_ * 3);
  for (int row = 0; row < height_; ++row) {
    const std::uint8_t* from = &rgba_[static_cast<std::size_t>(height_ - 1 - row) * width_ * 4];
    std::uint8_t* to = &out.data[static_cast<std::size_t>(row) * width_ * 3];
    for (int x = 0; x < width_; ++x)
      to[3 * x] = from[4 * x], to[3 * x + 1] = from[4 * x + 1], to[3 * x + 2] = from[4 * x + 2];
  }
  out.depth.clear();
  if (!depth) return;
  depth_.resize(static_cast<std::size_t>(width_) * height_);
  glReadPixels(0, 0, width_, height_, GL_DEPTH_COMPONENT, GL_FLOAT, depth_.data());
  out.depth.resize(depth_.size());
  const double n = view.near, f = view.far;
  for (int row = 0; row < height_; ++row)
    for (int x = 0; x < width_; ++x) {
      const double d = depth_[static_cast<std::size_t>(height_ - 1 - row) * width_ + x];
      out.depth[static_cast<std::size_t>(row) * width_ + x] =
          d >= 1 ? std::numeric_limits<float>::infinity()
                 : static_cast<float>(2 * f * n / (f + n - (2 * d - 1) * (f - n)));
    }
}

}  // namespace sanet::sensors
