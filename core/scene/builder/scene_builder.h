// SceneBuilder: the RiTarget that keeps the RI graphics state and builds one Scene per frame
// (per WorldBegin/WorldEnd block). Each finished frame is handed to a callback, so a
// 50-frame file never holds more than one scene.
#pragma once

#include "core/scene/builder/graphics_state.h"
#include "core/geometry/surfaces/quadric_tessellation.h"
#include "core/scene/ris/ris_patterns.h"
#include "core/scene/scene.h"
#include "core/geometry/surfaces/dicing_view.h"
#include "core/geometry/surfaces/triangle_mesh_data.h"
#include "core/math/transform_interpolation.h"
#include "parser/diagnostics.h"
#include "parser/ri_target.h"

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <unordered_map>
#include <vector>

namespace darc {

struct PatchMeshDescription;  // core/geometry/surfaces/patches/patch_tessellation.h

struct FrameOverrides {
  int xres = 0, yres = 0;             // --res (0: keep Format)
  double pixel_samples = 0;           // --pixel-samples (0: keep PixelSamples)
  // --crop xmin xmax ymin ymax: replaces every frame's CropWindow (unset: keep CropWindow).
  std::optional<std::array<double, 4>> crop;
  std::string output;                 // -o (empty: keep Display name)
  // The memory a frame's geometry may take (core/scene/frame_memory.h estimates it request by request);
  // a frame over it fails with an error naming the request that crossed it and is not rendered.
  // 0: no limit. The source says where the limit comes from, for the message.
  uint64_t memory_limit_bytes = 0;
  std::string memory_limit_source;
  // The folder Display names must stay inside (canonical; core/display_confinement.h); a name
  // that leaves it is an error at the Display request, and the frame is written under the name's
  // last component in this folder. Empty: anywhere (-o names the output, or --trust-rib).
  std::string display_folder;
};

class SceneBuilder : public RiTarget {
 public:
  // frame_ready is called at each WorldEnd of a selected frame, errors or not: a request with an
  // error was reported and skipped, and the frame is built from the rest (RI ErrorHandler
  // "print"); Diagnostics::frame_errors() holds what the frame's image must record. After the
  // callback the frame's errors are closed (Diagnostics::end_frame). frame_failed is called for
  // a frame whose world block never closes (the input ends inside it): nothing is rendered.
  // Under ErrorHandler "abort" no frame is handed over once an error arrived.
  struct Callbacks {
    std::function<bool(int frame_number)> frame_selected;  // may be empty: all frames
    std::function<void(Scene&&)> frame_ready;
    std::function<void(int frame_number)> frame_failed;
  };

  SceneBuilder(Diagnostics& diag, Callbacks callbacks, FrameOverrides overrides = {});
  ~SceneBuilder() override;

  int frames_rendered() const { return frames_ready_; }
  int frames_failed() const { return frames_failed_; }
  // Reports unclosed blocks at the end of input (call after parsing).
  void finish(const SourceLoc& end);

  // RiTarget
  void replayed_request(uint64_t id) override { replayed_id_ = id; }
  // Every request of parser/ri_requests.def. Where each is built: options in
  // scene_builder_options.cpp, RIS requests (mapped to darc's shaders and lights) in
  // scene_builder_ris.cpp, Sphere and the other primitives (one entry point that dispatches on the
  // request's name) in scene_builder_primitives.cpp, the rest by concern in scene_builder_*.cpp.
#include "parser/ri_target_overrides.inc"

  // Not wanted in a frame that is not rendered; the area is the bound's projection clipped to the
  // image (scene_builder_procedural.cpp).
  ProceduralBound procedural_bound(const std::array<double, 6>& bound, const SourceLoc& loc) override;

 private:
  enum class Block { Frame, World, Attribute, Transform, Object };

  void push_block(Block b, const SourceLoc& loc);
  void pop_block(Block b, const char* request, const SourceLoc& loc);
  // WorldEnd with AttributeBegin, TransformBegin or ObjectBegin blocks still open: each is an
  // error and is closed here, so that one missing AttributeEnd does not lose the frame.
  void close_blocks_left_open_in_world(const SourceLoc& loc);
  void set_ctm(const Matrix4& m);
  void concat(const Matrix4& m);
  // The texture files `shader`'s parameters name (names_a_texture), found along the texture search
  // path and made full paths; one not found is a warning at `loc` (its name cleared: the shader
  // goes without it, as `fallback` says).
  void resolve_texture_names(const char* request, const std::string& shader, ParamList& params,
                             const char* fallback, const SourceLoc& loc);
  bool in_world() const { return in_world_; }
  // False while skipping an unselected frame or recording an object: geometry is not built.
  bool building_geometry(const char* request, const SourceLoc& loc);
  // Adds a geometry request's memory estimate to the frame's (FrameOverrides::memory_limit_bytes).
  // Throws RibError at the request that takes the frame over the limit; false for the frame's
  // later geometry, which is no longer built.
  bool reserve_frame_memory(uint64_t curve_segments, uint64_t surfaces, uint64_t polygon_points);
  // The image's share of the frame's memory (core/frame_memory.h), counted at WorldBegin with the
  // geometry that follows; a frame whose image alone takes it over the limit fails at WorldEnd,
  // before the image is allocated.
  void count_image_memory(const OutputSettings& out);
  void check_frame_memory_at_world_end(const SourceLoc& loc);
  std::string frame_memory_error(const char* with) const;
  // The id of the cached-archive call being replayed (RiTarget::replayed_request), 0 for any other.
  uint64_t replayed_id() const;
  // Adds a geometry request to the frame's geometry key (Scene::geometry_key); a request that
  // is not a replayed one leaves the frame without a key.
  void note_geometry(uint64_t id);
  // Options may only change outside the world block.
  bool option_allowed(const char* request, const SourceLoc& loc);
  // The Display name to keep: `name`, or when it leaves FrameOverrides::display_folder, an error
  // at the request and the name the frame is written to instead.
  std::string confined_display_name(const std::string& name, const SourceLoc& loc);
  uint32_t make_material(const SourceLoc& loc);
  bool object_space_left_handed() const;
  Vec3f to_world(const float* p) const;
  void start_scene(const SourceLoc& loc);
  // The camera checks that need the frame's final state (scene_builder_frame_checks.cpp): the
  // frame aspect ratio, clamped to where the screen window stays within float range, and a crop
  // window that must cover a pixel (else an error at the CropWindow, or at WorldBegin for
  // --crop, and no crop).
  double checked_frame_aspect(double aspect, const SourceLoc& world_begin);
  // The current transform as the world-to-camera transform: the identity (with a warning) when
  // it is singular, as the camera must be inverted.
  Matrix4 checked_camera_transform(const SourceLoc& world_begin);
  void check_crop_window(OutputSettings& out, const SourceLoc& world_begin);
  // casts_shadows: given by a RIS Light; else from "shadowname" and Attribute "light". `request`:
  // the RIB request that declared it, as its warnings name it.
  void add_light(const std::string& name, const std::string& handle, const ParamList& params, const SourceLoc& loc,
                 std::optional<bool> casts_shadows = std::nullopt, const char* request = "LightSource");
  // The builders behind primitive(), one per request (after the common checks: not recording
  // an object, in the world, the frame built, the geometry noted).
  using PrimitiveBuilder = void (SceneBuilder::*)(const PrimitiveRequest&, const ParamList&, const SourceLoc&);
  static PrimitiveBuilder find_primitive_builder(const std::string& request);
  void add_sphere(const PrimitiveRequest& r, const ParamList& params, const SourceLoc& loc);
  // The other quadrics (scene_builder_quadrics.cpp).
  void add_cone(const PrimitiveRequest& r, const ParamList& params, const SourceLoc& loc);
  void add_cylinder(const PrimitiveRequest& r, const ParamList& params, const SourceLoc& loc);
  void add_disk(const PrimitiveRequest& r, const ParamList& params, const SourceLoc& loc);
  void add_paraboloid(const PrimitiveRequest& r, const ParamList& params, const SourceLoc& loc);
  void add_hyperboloid(const PrimitiveRequest& r, const ParamList& params, const SourceLoc& loc);
  void add_torus(const PrimitiveRequest& r, const ParamList& params, const SourceLoc& loc);
  void add_quadric(Quadric quadric, const PrimitiveRequest& r, const SourceLoc& loc);
  // SubdivisionMesh, tessellated to its limit surface (scene_builder_subdivision.cpp).
  void add_subdivision_mesh(const PrimitiveRequest& r, const ParamList& params, const SourceLoc& loc);
  // Patch, PatchMesh and NuPatch, tessellated (scene_builder_patches.cpp).
  void add_patch(const PrimitiveRequest& r, const ParamList& params, const SourceLoc& loc);
  void add_patch_mesh(const PrimitiveRequest& r, const ParamList& params, const SourceLoc& loc);
  void add_patch_surface(PatchMeshDescription& mesh, const ParamList& params, const char* request,
                         const SourceLoc& loc);
  void add_nu_patch(const PrimitiveRequest& r, const ParamList& params, const SourceLoc& loc);
  // The frame's camera seen from the current object space, for tessellations that follow the
  // screen (dicing_view.h); none outside the world block.
  std::optional<DicingView> dicing_view() const;
  // Points, sub-pixel discs beside the curves (scene_builder_points.cpp).
  void add_points(const PrimitiveRequest& r, const ParamList& params, const SourceLoc& loc);
  // Moves a tessellated surface from the current object space to the world and stores it with
  // `material` (from make_material). Returns how many triangles were kept (degenerate ones and
  // those beyond the float range in world space are dropped); false from reserve_frame_memory
  // adds nothing.
  // With motion blur on and a moving transform or motion samples (`samples`: the mesh's "P" at
  // RIB times, as many points as object_space.P), the mesh moves (TriangleStore::add_moving).
  struct PositionSample;
  size_t add_triangle_mesh(const TriangleMeshData& object_space, uint32_t material,
                           const std::vector<PositionSample>* samples = nullptr);
  // The four polygon requests: a sample of a motion block (built at MotionEnd) or add_polygons.
  void polygons_request(const char* request, const std::vector<int>& nloops_per_face,
                        const std::vector<int>& nverts_per_loop, const std::vector<int>& indices,
                        const ParamList& params, const SourceLoc& loc);
  // The common body of the four polygon requests; `samples`: the positions at a motion block's
  // times (empty: the request's own "P").
  void add_polygons(const std::vector<int>& nloops_per_face, const std::vector<int>& nverts_per_loop,
                    const std::vector<int>& indices, const ParamList& params, const char* request,
                    const SourceLoc& loc, const std::vector<PositionSample>* samples = nullptr);
  // Moving polygons become a moving triangle mesh (each face a fan): false, adding nothing, when a
  // face has holes or is not convex (the caller then builds them at shutter open, warned).
  bool add_moving_polygons(const std::vector<int>& nloops_per_face, const std::vector<int>& nverts_per_loop,
                           const std::vector<int>& indices, const std::vector<float>& P, uint32_t material,
                           const std::vector<PositionSample>& samples);
  // The ray-tracing conventions (scene_builder_ray_tracing.cpp). One parameter of an Attribute
  // "light", "visibility" or "render" request:
  void ray_tracing_attribute(const std::string& category, const Param& param, const SourceLoc& loc);
  // Option "trace": the reflection and refraction depth.
  void trace_option(const ParamList& params, const SourceLoc& loc);
  // Sets the transmission from a spelling that may ask for shader-computed opacity.
  void set_transmission(Transmission t, bool asks_for_shader_opacity, const SourceLoc& loc);
  // Whether a light being declared casts ray-traced shadows ("shadowname", Attribute "light").
  bool light_casts_shadows(const std::string& handle, const ParamList& params, const SourceLoc& loc);
  // Attribute "Ri" (scene_builder_ri_attribute.cpp): RenderMan 21+ spellings of RI requests as
  // attributes; "Basis" and "BasisStep" set the curve basis as Basis does.
  void ri_attribute(const ParamList& params, const SourceLoc& loc);
  // At WorldEnd (scene_builder_renderable.cpp): one warning when the frame has nothing that can
  // show up in its image, with the reason.
  void warn_if_nothing_renderable(const Scene& scene, const SourceLoc& loc);
  // Motion blocks (scene_builder_motion.cpp).
  // A transform request inside a motion block: recorded as a sample (true), applied at MotionEnd.
  // `absolute`: it replaces the current transform (Transform, Identity) instead of concatenating.
  bool transform_sample(const char* request, const Matrix4& m, bool absolute, const SourceLoc& loc);
  // A sample of a motion block: counted, and checked to be the block's request (false, reported,
  // when it is not: the block then keeps its first sample).
  bool count_motion_sample(const std::string& request, const SourceLoc& loc);
  struct MotionBlock;
  void end_transform_motion(const MotionBlock& block);
  void end_curves_motion(const MotionBlock& block);
  void end_polygons_motion(const MotionBlock& block);
  // A motion block of a tessellated surface (SubdivisionMesh, Patch, PatchMesh, NuPatch): each
  // sample tessellated; when every sample gives the same triangles (the usual case of a deforming
  // mesh), one moving mesh, else the first sample without motion blur (warned).
  void end_tessellated_motion(const MotionBlock& block);
  // Whether the shutter is open for a while (Shutter open < close): then things move.
  bool motion_blur() const { return options_.output.shutter_close > options_.output.shutter_open; }
  // The current transform at RIB time t.
  Matrix4 ctm_at(double t) const { return ctm_keys_.empty() ? ctm_ : transform_at(ctm_keys_, t); }
  void camera_shutter_opening(const Param& p, const SourceLoc& loc);
  // Sets the current transform to m relative to the world (Identity, Transform inside the world):
  // under a moving camera, it moves with the world (world_keys_).
  void set_world_relative_ctm(const Matrix4& m);
  // One Curves call's shape at its motion samples: RIB time and its "P" (or "Pw").
  struct PositionSample {
    double time;
    std::vector<float> P;
  };
  // The positions at RIB time t of the samples (linear between them, held beyond the first and
  // last).
  static std::vector<float> positions_at(const std::vector<PositionSample>& samples, double t);
  // The RIB times at which something built now gets motion keys: shutter open and close, the
  // samples' times and the moving transform's keys between, and more where the transform turns
  // the object-space points P (xyz).
  std::vector<double> motion_key_times(const std::vector<PositionSample>& samples, const std::vector<float>& P) const;
  // Key times with more keys where the moving transform turns the points P (object space).
  std::vector<double> refine_turning_keys(const std::vector<double>& times, const std::vector<float>& P) const;
  // Curves with its positions at motion samples (empty: the call's own "P", not moving unless the
  // transform moves).
  void build_curves(const std::string& type, const std::vector<int>& nvertices, const std::string& wrap,
                    const ParamList& params, const std::vector<PositionSample>& samples, const SourceLoc& loc);
  // When recording an ObjectBegin block, stores the call and returns true.
  bool record(std::function<void(SceneBuilder&)> call);

  Diagnostics& diag_;
  Callbacks callbacks_;
  FrameOverrides overrides_;

  Options options_;
  std::vector<Options> saved_options_;  // FrameBegin pushes, FrameEnd pops
  Attributes attributes_;
  std::vector<Attributes> saved_attributes_;
  Matrix4 ctm_;  // before WorldBegin: current -> camera; inside: current -> world
  std::vector<Matrix4> saved_ctm_;
  // The current transform over RIB time while it moves (a motion block around a transform, or
  // one of the enclosing scope's), sorted by time; empty: ctm_ at every time. ctm_ is then the
  // transform at shutter open, which everything that does not move uses.
  std::vector<TransformKey> ctm_keys_;
  std::vector<std::vector<TransformKey>> saved_ctm_keys_;
  // A moving camera (a motion block before WorldBegin, shutter open): the image is rendered from
  // the camera at shutter open, and the world moves instead, by W2C(t) W2C(open)^-1 at RIB time
  // t; these are its keys (empty: the camera does not move).
  std::vector<TransformKey> world_keys_;
  // While a motion block's tessellated samples are tessellated (end_tessellated_motion):
  // add_triangle_mesh hands its meshes here instead of adding them.
  struct CapturedMesh {
    TriangleMeshData mesh;
    uint32_t material;
  };
  std::vector<CapturedMesh>* captured_meshes_ = nullptr;
  // While a moving Points request is built key by key (add_moving_points): add_points adds to this
  // set instead of the scene's, and reports its warnings only for the first key.
  PointSet* captured_points_ = nullptr;
  bool later_motion_key_ = false;
  // The grid of the first captured quadric sample, so that every sample of the block gets it.
  std::optional<QuadricGrid> captured_grid_;
  // A quadric that moves (a moving transform, or a sample of a motion block): tessellated.
  bool quadric_moves() const { return captured_meshes_ != nullptr || (motion_blur() && !ctm_keys_.empty()); }
  // The grid a moving quadric is tessellated on: its own, or the first sample's in a block.
  QuadricGrid moving_quadric_grid(const QuadricGrid& own);
  std::vector<Block> blocks_;
  std::vector<SourceLoc> block_locs_;

  bool in_world_ = false;
  bool in_frame_ = false;
  bool frame_skipped_ = false;  // --frames did not select this frame
  int frame_number_ = 0;
  bool has_frame_number_ = false;
  int world_blocks_seen_ = 0;
  int frames_ready_ = 0, frames_failed_ = 0;

  std::unique_ptr<Scene> scene_;  // the frame being built (inside the world block)
  uint64_t frame_memory_estimate_ = 0;  // core/scene/frame_memory.h, of the image and the geometry built so far
  uint64_t image_memory_ = 0;           // the image's part of it
  bool frame_over_memory_ = false;      // the frame went over memory_limit_bytes: not rendered
  // Archive reuse (parser/archive_cache.h): the id of the replayed call being made, the curves
  // built from each replayed Curves call with what they depend on besides the call itself
  // (kept from one frame to the next while used), and the frame's geometry key.
  uint64_t replayed_id_ = 0;
  struct CurveChunk {
    Matrix4 ctm;
    CurveBasis basis;
    Vec3f color, opacity;
    CurveSet segments;  // strand ids from 0
    uint32_t strands = 0;
    bool used = false;  // this frame
  };
  std::unordered_map<uint64_t, CurveChunk> curve_chunks_;
  std::string geometry_key_;
  bool geometry_key_valid_ = true;
  // The attribute state a material was made from (make_material interns materials by it). The
  // key holds its parameter lists, so that an address is never reused by another list while it
  // is a key.
  struct MaterialKey {
    std::string surface;
    std::shared_ptr<const ParamList> surface_params;
    Vec3f color, opacity;
    int sides;
    bool flip_normals, matte;
    std::vector<uint32_t> lights;
    std::string area_light;
    std::shared_ptr<const ParamList> area_light_params;
    int area_light_index;
    Transmission transmission;
    auto tie() const {
      return std::make_tuple(std::cref(surface), surface_params.get(), color.x, color.y, color.z, opacity.x, opacity.y, opacity.z, sides,
                      flip_normals, matte, std::cref(lights), std::cref(area_light),
                             area_light_params.get(), area_light_index, transmission);
    }
    bool operator<(const MaterialKey& o) const { return tie() < o.tie(); }
  };
  std::map<MaterialKey, uint32_t> material_ids_;  // this frame's materials
  Matrix4 camera_to_world_;
  std::map<std::string, Matrix4> named_spaces_;  // CoordinateSystem, relative to world
  // ScopedCoordinateSystem: named until the end of the attribute block at `depth` (the number of
  // saved attribute states when it was given); the latest of a name first.
  struct ScopedSpace {
    std::string name;
    Matrix4 to_world;
    size_t depth;
  };
  std::vector<ScopedSpace> scoped_spaces_;
  std::map<std::string, uint32_t> light_handles_;
  // AreaLightSource handles, and those of RIS Lights darc does not know: valid for Illuminate,
  // though they light nothing in darc.
  std::set<std::string> area_light_handles_;
  RisPatterns ris_patterns_;  // RIS Pattern requests by handle, for Bxdf references
  // saved_attributes_.size() inside the world block: the states saved from there on are the
  // world's own (a RIS Light is switched on in all of them, scene_builder_ris.cpp).
  size_t world_attribute_depth_ = 0;
  // This frame's primitive requests that darc does not implement, by request name.
  std::map<std::string, int> skipped_primitives_;
  uint32_t next_strand_id_ = 0;

  // ObjectBegin/End: the calls of each object, replayed at ObjectInstance.
  std::map<std::string, std::vector<std::function<void(SceneBuilder&)>>> objects_;
  std::vector<std::function<void(SceneBuilder&)>>* recording_ = nullptr;
  bool replaying_ = false;
  // The open MotionBegin block: its times, the request its samples are, and what they hold.
  struct MotionBlock {
    std::vector<double> times;
    SourceLoc loc;
    std::string request;  // the first sample's request
    int samples = 0;
    bool failed = false;  // reported: the block keeps its first sample
    std::vector<Matrix4> matrices;  // transform samples
    bool absolute = false;
    struct CurvesSample {
      std::string type, wrap;
      std::vector<int> nvertices;
      ParamList params;
      SourceLoc loc;
    };
    std::vector<CurvesSample> curves;  // Curves samples
    struct PolygonsSample {
      std::string request;
      std::vector<int> nloops, nverts, indices;
      ParamList params;
      SourceLoc loc;
    };
    std::vector<PolygonsSample> polygons;  // Polygon, GeneralPolygon, PointsPolygons, ... samples
    struct PrimitiveSample {
      PrimitiveRequest request;
      ParamList params;
      SourceLoc loc;
    };
    std::vector<PrimitiveSample> tessellated;  // SubdivisionMesh, Patch, PatchMesh, NuPatch, quadric samples
    std::vector<PrimitiveSample> points;       // Points samples
  };
  std::optional<MotionBlock> motion_;
  // Points that move: samples of a motion block (their "P" and "width" at the block's times) or
  // one request under a moving transform or camera; built at every key time, then keyed.
  using MotionBlockSample = MotionBlock::PrimitiveSample;
  void add_moving_points(const std::vector<MotionBlockSample>& samples, const std::vector<double>& times);
};

}  // namespace darc
