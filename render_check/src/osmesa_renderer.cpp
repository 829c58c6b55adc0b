#include <rotorcert/render/osmesa_renderer.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>

#include <rotorcert/render/transform.hpp>

#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>

namespace rotorcert::render {

namespace {

// Every OpenGL entry point used, loaded through OSMesaGetProcAddress rather than linked, so that
// the code does not depend on which GL symbols libOSMesa happens to export. GL 1.x functions take
// their types from the prototypes of <GL/gl.h>, later ones from the PFN types of <GL/glext.h>.
#define ROTORCERT_GL_FUNCTIONS(X)                                   \
  X(decltype(&::glViewport), Viewport)                              \
  X(decltype(&::glClearColor), ClearColor)                          \
  X(decltype(&::glClearDepth), ClearDepth)                          \
  X(decltype(&::glClear), Clear)                                    \
  X(decltype(&::glEnable), Enable)                                  \
  X(decltype(&::glDisable), Disable)                                \
  X(decltype(&::glDepthFunc), DepthFunc)                            \
  X(decltype(&::glReadBuffer), ReadBuffer)                          \
  X(decltype(&::glReadPixels), ReadPixels)                          \
  X(decltype(&::glPixelStorei), PixelStorei)                        \
  X(decltype(&::glDrawElements), DrawElements)                      \
  X(decltype(&::glGetError), GetError)                              \
  X(decltype(&::glGetString), GetString)                            \
  X(decltype(&::glGetIntegerv), GetIntegerv)                        \
  X(PFNGLCREATESHADERPROC, CreateShader)                            \
  X(PFNGLSHADERSOURCEPROC, ShaderSource)                            \
  X(PFNGLCOMPILESHADERPROC, CompileShader)                          \
  X(PFNGLGETSHADERIVPROC, GetShaderiv)                              \
  X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)                    \
  X(PFNGLDELETESHADERPROC, DeleteShader)                            \
  X(PFNGLCREATEPROGRAMPROC, CreateProgram)                          \
  X(PFNGLATTACHSHADERPROC, AttachShader)                            \
  X(PFNGLLINKPROGRAMPROC, LinkProgram)                              \
  X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                            \
  X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)                  \
  X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                          \
  X(PFNGLUSEPROGRAMPROC, UseProgram)                                \
  X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)                \
  X(PFNGLUNIFORM1IPROC, Uniform1i)                                  \
  X(PFNGLUNIFORM3FVPROC, Uniform3fv)                                \
  X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)                    \
  X(PFNGLGENBUFFERSPROC, GenBuffers)                                \
  X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                          \
  X(PFNGLBINDBUFFERPROC, BindBuffer)                                \
  X(PFNGLBUFFERDATAPROC, BufferData)                                \
  X(PFNGLBINDBUFFERBASEPROC, BindBufferBase)                        \
  X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                      \
  X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)                \
  X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                      \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray)      \
  X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)              \
  X(PFNGLVERTEXATTRIBIPOINTERPROC, VertexAttribIPointer)            \
  X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                      \
  X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)                \
  X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                      \
  X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer)      \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)        \
  X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers)                    \
  X(PFNGLDELETERENDERBUFFERSPROC, DeleteRenderbuffers)              \
  X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer)                    \
  X(PFNGLRENDERBUFFERSTORAGEPROC, RenderbufferStorage)

struct Gl {
#define ROTORCERT_GL_MEMBER(type, name) type name = nullptr;
  ROTORCERT_GL_FUNCTIONS(ROTORCERT_GL_MEMBER)
#undef ROTORCERT_GL_MEMBER

  void load() {
#define ROTORCERT_GL_LOAD(type, name)                                                        \
  name = reinterpret_cast<type>(OSMesaGetProcAddress("gl" #name));                           \
  if (name == nullptr) throw RenderError("OSMesaGetProcAddress found no gl" #name);
    ROTORCERT_GL_FUNCTIONS(ROTORCERT_GL_LOAD)
#undef ROTORCERT_GL_LOAD
  }
};

// Skinning in the vertex shader. Modes: 0 linear blend, 1 dual quaternion, 2 pass-through (the
// SkinningMode documentation in the header states the formulas). Palettes are shader storage
// buffers so that their size is not bounded by the uniform limits.
constexpr const char* kVertexShader = R"glsl(#version 450 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in uvec4 a_joints;
layout(location = 3) in vec4 a_weights;

// std430 mat4 is 16 floats, column-major: the Mat4 layout of types.hpp.
layout(std430, binding = 0) readonly buffer Matrices { mat4 palette_matrices[]; };
// Two vec4 per joint: the real part, then the dual part, each [x, y, z, w].
layout(std430, binding = 1) readonly buffer DualQuaternions { vec4 palette_dq[]; };

uniform int u_mode;
uniform mat4 u_view_projection;

out vec3 v_normal;

// v rotated by the unit quaternion r (vector part r.xyz, scalar r.w).
vec3 rotate(vec4 r, vec3 v) { return v + 2.0 * cross(r.xyz, cross(r.xyz, v) + r.w * v); }

void main() {
  vec3 p = a_position;
  vec3 n = a_normal;
  if (u_mode == 0) {
    mat4 m = a_weights.x * palette_matrices[a_joints.x] + a_weights.y * palette_matrices[a_joints.y] +
             a_weights.z * palette_matrices[a_joints.z] + a_weights.w * palette_matrices[a_joints.w];
    p = (m * vec4(a_position, 1.0)).xyz;
    // Renormalised per vertex, as CPU skinning does, so that the rasteriser interpolates unit
    // normals whichever side skinned them (blended matrices shrink normals unevenly).
    n = normalize(mat3(m) * a_normal);
  } else if (u_mode == 1) {
    // Hemisphere alignment to the pivot, the first influence of weight > 0.
    int pivot = 0;
    for (int k = 3; k >= 0; --k)
      if (a_weights[k] > 0.0) pivot = k;
    vec4 real_pivot = palette_dq[2u * a_joints[pivot]];
    vec4 blend_real = vec4(0.0);
    vec4 blend_dual = vec4(0.0);
    for (int k = 0; k < 4; ++k) {
      float w = a_weights[k];
      if (w > 0.0) {
        vec4 r = palette_dq[2u * a_joints[k]];
        vec4 d = palette_dq[2u * a_joints[k] + 1u];
        if (dot(r, real_pivot) < 0.0) w = -w;
        blend_real += w * r;
        blend_dual += w * d;
      }
    }
    float len = length(blend_real);
    vec4 r = blend_real / len;
    vec4 d = blend_dual / len;
    // t = 2 d conj(r): its vector part is 2 (r_w d_v - d_w r_v + r_v x d_v).
    p = rotate(r, a_position) + 2.0 * (r.w * d.xyz - d.w * r.xyz + cross(r.xyz, d.xyz));
    n = rotate(r, a_normal);
  }
  v_normal = n;
  gl_Position = u_view_projection * vec4(p, 1.0);
}
)glsl";

constexpr const char* kFragmentShader = R"glsl(#version 450 core
in vec3 v_normal;
uniform vec3 u_light;   // unit vector toward the light, world space
uniform vec3 u_colour;  // material colour, 0..1
out vec4 frag_colour;

void main() {
  vec3 n = normalize(v_normal);
  // Culling is off, so back faces are seen: light them as their visible side.
  if (!gl_FrontFacing) n = -n;
  float diffuse = max(dot(n, u_light), 0.0);
  frag_colour = vec4(u_colour * (0.25 + 0.75 * diffuse), 1.0);
}
)glsl";

/// Interleaved vertex as uploaded: 56 bytes, attribute locations 0..3 of the vertex shader.
struct GpuVertex {
  float position[3];
  float normal[3];
  std::uint32_t joints[4];
  float weights[4];
};
static_assert(sizeof(GpuVertex) == 56);

bool finite(const Vec3& v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }
template <std::size_t N>
bool finite(const std::array<double, N>& v) {
  return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

std::string draw_name(std::size_t i, const MeshDraw& d) {
  return "mesh " + std::to_string(i) + (d.mesh && !d.mesh->name.empty() ? " (" + d.mesh->name + ")" : std::string());
}

std::optional<std::string> validate_draw(std::size_t i, const MeshDraw& d) {
  const std::string name = draw_name(i, d);
  if (d.mesh == nullptr) return name + ": no mesh";
  const SkinnedMesh& m = *d.mesh;
  const std::size_t n = m.positions.size();
  if (n == 0 || m.indices.empty()) return name + ": no vertices or no triangles";
  if (n > std::numeric_limits<std::uint32_t>::max()) return name + ": too many vertices";
  if (m.indices.size() % 3 != 0) return name + ": index count is not a multiple of 3";
  for (std::uint32_t index : m.indices)
    if (index >= n) return name + ": index " + std::to_string(index) + " >= vertex count " + std::to_string(n);

  if (d.mode == SkinningMode::pass_through) {
    if (d.positions.size() != n || d.normals.size() != n)
      return name + ": pass_through needs one skinned position and normal per vertex (" + std::to_string(n) + ")";
    for (std::size_t v = 0; v < n; ++v)
      if (!finite(d.positions[v]) || !finite(d.normals[v])) return name + ": skinned vertex " + std::to_string(v) + " not finite";
    return std::nullopt;
  }

  if (m.normals.size() != n) return name + ": normal count differs from position count";
  if (m.joints.size() != n || m.weights.size() != n) return name + ": joints/weights count differs from position count";
  const std::size_t palette = d.mode == SkinningMode::linear_blend ? d.matrices.size() : d.dual_quaternions.size();
  if (palette == 0) return name + ": empty palette for " + to_string(d.mode);
  if (palette > RenderJob::kMaxPaletteSize) return name + ": palette larger than " + std::to_string(RenderJob::kMaxPaletteSize);
  for (std::size_t v = 0; v < n; ++v) {
    if (!finite(m.positions[v]) || !finite(m.normals[v]) || !finite(m.weights[v]))
      return name + ": vertex " + std::to_string(v) + " not finite";
    // Without a positive weight the blend is zero (LBS) or has no pivot (DQS).
    if (std::none_of(m.weights[v].begin(), m.weights[v].end(), [](double w) { return w > 0.0; }))
      return name + ": vertex " + std::to_string(v) + " has no positive weight";
    for (std::size_t k = 0; k < 4; ++k)
      if (m.joints[v][k] >= palette)
        return name + ": vertex " + std::to_string(v) + " uses joint " + std::to_string(m.joints[v][k]) +
               " but the palette has " + std::to_string(palette) + " entries";
  }
  if (d.mode == SkinningMode::linear_blend) {
    for (std::size_t j = 0; j < palette; ++j)
      if (!finite(d.matrices[j])) return name + ": palette matrix " + std::to_string(j) + " not finite";
  } else {
    for (std::size_t j = 0; j < palette; ++j) {
      const DualQuaternion& q = d.dual_quaternions[j];
      if (!finite(q.real) || !finite(q.dual)) return name + ": palette dual quaternion " + std::to_string(j) + " not finite";
      if (q.real == Quat{0.0, 0.0, 0.0, 0.0}) return name + ": palette dual quaternion " + std::to_string(j) + " has a zero real part";
    }
  }
  return std::nullopt;
}

std::array<float, 16> to_float(const Mat4& m) {
  std::array<float, 16> f{};
  for (std::size_t i = 0; i < 16; ++i) f[i] = static_cast<float>(m[i]);
  return f;
}

}  // namespace

}  // namespace rotorcert::render

// Mesa's OSMesa never frees the framebuffer records OSMesaMakeCurrent keeps in a global list (a
// program that only creates, makes current and destroys one context leaks them too), so under
// LeakSanitizer (the asan preset runs with detect_leaks=1) every program that renders would fail
// on Mesa's leak. This suppresses leaks allocated inside libOSMesa only. Weak, so that a program
// defining its own suppressions takes precedence (it should then list libOSMesa too).
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define ROTORCERT_RENDER_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(ROTORCERT_RENDER_ASAN)
extern "C" __attribute__((weak)) const char* __lsan_default_suppressions() { return "leak:libOSMesa.so\n"; }
#endif

namespace rotorcert::render {

const char* to_string(SkinningMode mode) {
  switch (mode) {
    case SkinningMode::linear_blend: return "linear_blend";
    case SkinningMode::dual_quaternion: return "dual_quaternion";
    case SkinningMode::pass_through: return "pass_through";
  }
  return "unknown";
}

std::optional<std::string> RenderJob::validate() const {
  if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide)
    return "image size " + std::to_string(width) + " x " + std::to_string(height) + " outside 1.." + std::to_string(kMaxImageSide);
  try {
    (void)view_matrix(camera);
    (void)projection_matrix(camera, static_cast<double>(width) / height);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  if (meshes.empty()) return "no meshes to draw";
  for (std::size_t i = 0; i < meshes.size(); ++i)
    if (auto problem = validate_draw(i, meshes[i])) return problem;
  return std::nullopt;
}

struct OsmesaRenderer::State {
  OSMesaContext context = nullptr;
  // OSMesa needs a colour buffer to make the context current; frames are drawn into `framebuffer`
  // instead, whose formats (RGBA8, 24-bit depth, one sample) are chosen here, not by OSMesa.
  std::array<std::uint8_t, 4> dummy{};
  Gl gl;
  GLuint program = 0;
  GLint u_mode = -1, u_view_projection = -1, u_light = -1, u_colour = -1;
  GLuint vao = 0, vertex_buffer = 0, index_buffer = 0, matrix_buffer = 0, dq_buffer = 0;
  GLuint framebuffer = 0, colour_buffer = 0, depth_buffer = 0;
  int fb_width = 0, fb_height = 0;

  void make_current() {
    if (!OSMesaMakeCurrent(context, dummy.data(), GL_UNSIGNED_BYTE, 1, 1))
      throw RenderError("OSMesaMakeCurrent failed");
  }

  void check_gl(const char* where) {
    const GLenum error = gl.GetError();
    if (error != GL_NO_ERROR) {
      while (gl.GetError() != GL_NO_ERROR) {
      }
      throw RenderError(std::string("OpenGL error 0x") + [&] {
        char hex[16];
        std::snprintf(hex, sizeof hex, "%04x", static_cast<unsigned>(error));
        return std::string(hex);
      }() + " in " + where);
    }
  }

  GLuint compile(GLenum type, const char* source) {
    const GLuint shader = gl.CreateShader(type);
    gl.ShaderSource(shader, 1, &source, nullptr);
    gl.CompileShader(shader);
    GLint ok = 0;
    gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
      std::array<char, 4096> log{};
      gl.GetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
      gl.DeleteShader(shader);
      throw RenderError(std::string(type == GL_VERTEX_SHADER ? "vertex" : "fragment") + " shader does not compile: " + log.data());
    }
    return shader;
  }

  void build_program() {
    const GLuint vs = compile(GL_VERTEX_SHADER, kVertexShader);
    const GLuint fs = compile(GL_FRAGMENT_SHADER, kFragmentShader);
    program = gl.CreateProgram();
    gl.AttachShader(program, vs);
    gl.AttachShader(program, fs);
    gl.LinkProgram(program);
    gl.DeleteShader(vs);  // flagged for deletion; they live as long as the program
    gl.DeleteShader(fs);
    GLint ok = 0;
    gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
      std::array<char, 4096> log{};
      gl.GetProgramInfoLog(program, static_cast<GLsizei>(log.size()), nullptr, log.data());
      throw RenderError(std::string("shader program does not link: ") + log.data());
    }
    u_mode = gl.GetUniformLocation(program, "u_mode");
    u_view_projection = gl.GetUniformLocation(program, "u_view_projection");
    u_light = gl.GetUniformLocation(program, "u_light");
    u_colour = gl.GetUniformLocation(program, "u_colour");
    if (u_mode < 0 || u_view_projection < 0 || u_light < 0 || u_colour < 0)
      throw RenderError("shader program lacks a uniform");
  }

  void resize(int width, int height) {
    if (width == fb_width && height == fb_height) return;
    GLint max_size = 0;
    gl.GetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
    if (width > max_size || height > max_size)
      throw RenderError("image size " + std::to_string(width) + " x " + std::to_string(height) +
                        " exceeds GL_MAX_RENDERBUFFER_SIZE " + std::to_string(max_size));
    gl.BindRenderbuffer(GL_RENDERBUFFER, colour_buffer);
    gl.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    gl.BindRenderbuffer(GL_RENDERBUFFER, depth_buffer);
    gl.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_buffer);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_buffer);
    const GLenum status = gl.CheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) throw RenderError("framebuffer incomplete (status " + std::to_string(status) + ")");
    check_gl("framebuffer set-up");
    fb_width = width;
    fb_height = height;
  }

  void draw(const MeshDraw& d) {
    const SkinnedMesh& m = *d.mesh;
    const std::size_t n = m.positions.size();
    const bool pass = d.mode == SkinningMode::pass_through;
    std::vector<GpuVertex> vertices(n);
    for (std::size_t v = 0; v < n; ++v) {
      GpuVertex& g = vertices[v];
      const Vec3& p = pass ? d.positions[v] : m.positions[v];
      const Vec3& nn = pass ? d.normals[v] : m.normals[v];
      for (std::size_t i = 0; i < 3; ++i) {
        g.position[i] = static_cast<float>(p[i]);
        g.normal[i] = static_cast<float>(nn[i]);
      }
      for (std::size_t k = 0; k < 4; ++k) {
        g.joints[k] = pass ? 0u : m.joints[v][k];
        g.weights[k] = pass ? 0.0f : static_cast<float>(m.weights[v][k]);
      }
    }
    gl.BindVertexArray(vao);
    gl.BindBuffer(GL_ARRAY_BUFFER, vertex_buffer);
    gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(GpuVertex)), vertices.data(), GL_STREAM_DRAW);
    gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, index_buffer);
    gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(m.indices.size() * sizeof(std::uint32_t)), m.indices.data(),
                  GL_STREAM_DRAW);
    const auto offset = [](std::size_t bytes) { return reinterpret_cast<const void*>(bytes); };
    gl.EnableVertexAttribArray(0);
    gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(GpuVertex), offset(offsetof(GpuVertex, position)));
    gl.EnableVertexAttribArray(1);
    gl.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(GpuVertex), offset(offsetof(GpuVertex, normal)));
    gl.EnableVertexAttribArray(2);
    gl.VertexAttribIPointer(2, 4, GL_UNSIGNED_INT, sizeof(GpuVertex), offset(offsetof(GpuVertex, joints)));
    gl.EnableVertexAttribArray(3);
    gl.VertexAttribPointer(3, 4, GL_FLOAT, GL_FALSE, sizeof(GpuVertex), offset(offsetof(GpuVertex, weights)));

    // Both palette buffers are always bound (a shader storage block must have a buffer even when
    // its mode does not read it); the unused one holds one zero element.
    std::vector<float> matrices(16, 0.0f), dqs(8, 0.0f);
    if (d.mode == SkinningMode::linear_blend) {
      matrices.clear();
      for (const Mat4& mat : d.matrices) {
        const auto f = to_float(mat);
        matrices.insert(matrices.end(), f.begin(), f.end());
      }
    } else if (d.mode == SkinningMode::dual_quaternion) {
      dqs.clear();
      for (const DualQuaternion& q : d.dual_quaternions) {
        for (double x : q.real) dqs.push_back(static_cast<float>(x));
        for (double x : q.dual) dqs.push_back(static_cast<float>(x));
      }
    }
    gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, matrix_buffer);
    gl.BufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(matrices.size() * sizeof(float)), matrices.data(), GL_STREAM_DRAW);
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, matrix_buffer);
    gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, dq_buffer);
    gl.BufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(dqs.size() * sizeof(float)), dqs.data(), GL_STREAM_DRAW);
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, dq_buffer);

    const int mode = d.mode == SkinningMode::linear_blend ? 0 : d.mode == SkinningMode::dual_quaternion ? 1 : 2;
    gl.Uniform1i(u_mode, mode);
    const std::array<float, 3> colour{d.colour[0] / 255.0f, d.colour[1] / 255.0f, d.colour[2] / 255.0f};
    gl.Uniform3fv(u_colour, 1, colour.data());
    gl.DrawElements(GL_TRIANGLES, static_cast<GLsizei>(m.indices.size()), GL_UNSIGNED_INT, nullptr);
    check_gl(("drawing " + std::string(to_string(d.mode))).c_str());
  }
};

OsmesaRenderer::OsmesaRenderer() : state_(std::make_unique<State>()) {
  // Mesa's OSMesa runs on the llvmpipe software rasteriser; a 4.5 core profile has shader storage
  // buffers and integer vertex attributes, which the skinning shaders use.
  const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0, OSMESA_STENCIL_BITS, 0, OSMESA_ACCUM_BITS, 0,
                            OSMESA_PROFILE, OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 4,
                            OSMESA_CONTEXT_MINOR_VERSION, 5, 0};
  State& s = *state_;
  s.context = OSMesaCreateContextAttribs(attributes, nullptr);
  if (s.context == nullptr)
    throw RenderError("OSMesa could not create an OpenGL 4.5 core profile context (OSMesaCreateContextAttribs returned "
                      "NULL); the renderer needs Mesa's OSMesa with the llvmpipe driver");
  try {
    s.make_current();
    s.gl.load();
    s.build_program();
    s.gl.GenVertexArrays(1, &s.vao);
    GLuint buffers[4];
    s.gl.GenBuffers(4, buffers);
    s.vertex_buffer = buffers[0];
    s.index_buffer = buffers[1];
    s.matrix_buffer = buffers[2];
    s.dq_buffer = buffers[3];
    s.gl.GenFramebuffers(1, &s.framebuffer);
    GLuint renderbuffers[2];
    s.gl.GenRenderbuffers(2, renderbuffers);
    s.colour_buffer = renderbuffers[0];
    s.depth_buffer = renderbuffers[1];
    s.check_gl("renderer set-up");
  } catch (...) {
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(s.context);
    throw;
  }
}

OsmesaRenderer::~OsmesaRenderer() {
  State& s = *state_;
  if (OSMesaMakeCurrent(s.context, s.dummy.data(), GL_UNSIGNED_BYTE, 1, 1)) {
    s.gl.DeleteProgram(s.program);
    s.gl.DeleteVertexArrays(1, &s.vao);
    const GLuint buffers[4] = {s.vertex_buffer, s.index_buffer, s.matrix_buffer, s.dq_buffer};
    s.gl.DeleteBuffers(4, buffers);
    s.gl.DeleteFramebuffers(1, &s.framebuffer);
    const GLuint renderbuffers[2] = {s.colour_buffer, s.depth_buffer};
    s.gl.DeleteRenderbuffers(2, renderbuffers);
  }
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(s.context);
}

std::string OsmesaRenderer::description() const {
  state_->make_current();
  const auto text = [&](GLenum name) {
    const GLubyte* s = state_->gl.GetString(name);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
  };
  return text(GL_RENDERER) + "; " + text(GL_VERSION);
}

Image OsmesaRenderer::run(const RenderJob& job) {
  if (auto problem = job.validate()) throw std::invalid_argument("RenderJob: " + *problem);
  State& s = *state_;
  Gl& gl = s.gl;
  s.make_current();
  s.resize(job.width, job.height);

  gl.BindFramebuffer(GL_FRAMEBUFFER, s.framebuffer);
  gl.Viewport(0, 0, job.width, job.height);
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthFunc(GL_LESS);
  gl.Disable(GL_CULL_FACE);
  gl.Disable(GL_MULTISAMPLE);
  gl.Disable(GL_DITHER);  // dithering is allowed to vary the output; frames must be reproducible
  gl.Disable(GL_BLEND);
  gl.ClearColor(job.background[0] / 255.0f, job.background[1] / 255.0f, job.background[2] / 255.0f, job.background[3] / 255.0f);
  gl.ClearDepth(1.0);
  gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  const double aspect = static_cast<double>(job.width) / job.height;
  const auto view_projection = to_float(multiply(projection_matrix(job.camera, aspect), view_matrix(job.camera)));
  gl.UseProgram(s.program);
  gl.UniformMatrix4fv(s.u_view_projection, 1, GL_FALSE, view_projection.data());
  const float l = 1.0f / std::sqrt(0.3f * 0.3f + 0.8f * 0.8f + 0.5f * 0.5f);
  const std::array<float, 3> light{0.3f * l, 0.8f * l, 0.5f * l};
  gl.Uniform3fv(s.u_light, 1, light.data());
  for (const MeshDraw& d : job.meshes) s.draw(d);

  Image image = Image::filled(job.width, job.height, {0, 0, 0, 0});
  std::vector<std::uint8_t> rows(image.rgba.size());
  gl.ReadBuffer(GL_COLOR_ATTACHMENT0);
  gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl.ReadPixels(0, 0, job.width, job.height, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
  s.check_gl("reading the frame");
  // OpenGL's first row is the bottom one; Image's is the top one.
  const std::size_t row_bytes = std::size_t{4} * static_cast<std::size_t>(job.width);
  for (int y = 0; y < job.height; ++y)
    std::memcpy(image.rgba.data() + row_bytes * static_cast<std::size_t>(y),
                rows.data() + row_bytes * static_cast<std::size_t>(job.height - 1 - y), row_bytes);
  return image;
}

}  // namespace rotorcert::render
