// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__COMMON__FAKE_PHYSICS_MUJOCO_HPP_
#define ROBOT_HARDWARE_INTERFACE__COMMON__FAKE_PHYSICS_MUJOCO_HPP_

// The fake robot's joints on real physics (issue 36): the package's URDF compiled by MuJoCo's own
// URDF compiler, with gravity, a floor, contacts and the coupling between links, in place of the
// vacuum of fake_joint_dynamics.hpp. FakeMujocoPhysics<N> has FakeJointDynamics<N>'s interface
// (command, release, step, place, position, velocity, effort, last_command, ...), so the
// transport's fake side reads and writes either the same way; it adds load(), the IMU and the base.
// It is also a FakeJointEngine<N>: FakeJointDynamics::use_engine() hands the fake robot's joints to
// it at run time, the transports reading FakeJointDynamics as before.
//
// What it simulates:
// - the robot from the URDF: MuJoCo's URDF defaults (visual elements discarded, static bodies
//   fused, radians), the URDF's joint limits, <dynamics damping friction> and <inertial>s; each
//   joint of the table gets an armature (rotor inertia: FakeJointSpec::armature, the vendor
//   YAML's), and the table's passive damping and dry friction (FakeJointSpec::physics_damping,
//   frictionloss: the vendor YAML's joint_damping / joint_frictionloss, else the URDF's
//   <dynamics>);
// - meshes: `package://<pkg>/<path>` is looked up as <prefix>/share/<pkg>/<path> (and
//   <prefix>/<pkg>/<path>) under each prefix of FakePhysicsOptions::package_path, `file://` and
//   relative paths as MuJoCo does; when one cannot be found, every mesh geom is dropped and the
//   model is inertial-only (its primitive geoms stay), with one warning; the vendor YAML's
//   contacts (FakePhysicsOptions::contacts: its MuJoCo model's primitives, e.g. the feet's) then
//   stand in for the mesh collisions on their links, so that a free base still stands;
// - gravity (0, 0, -9.81) and a floor plane at z = 0;
// - the base (FakeBase): `free` (a free joint on the URDF's root link, the robot on the floor in
//   its start pose, held there as on its gantry until a motor is first commanded with a gain: a
//   driver's safe start holds the robot limp for a moment, and a robot standing on its own feet
//   would fold; the first gains let it go), `band` (free, held by an
//   elastic band: a spring-damper pulling a point fixed to the root link, band_arm above the
//   robot's centre of mass at its start pose, towards a point above where it started, applied
//   through xfrc_applied; the robot hangs from it like a pendulum, upright; release_band() lets
//   go) or `fixed` (no floating base: the root link is welded to the world where the URDF puts
//   it, and the floor lies below anything the robot can reach);
// - each motor under its vendor's law tau = kp (q_t - q) + kd (dq_t - dq) + tau_ff, clamped to the
//   joint's effort limit and applied as a generalized force (qfrc_applied), recomputed at every
//   physics step (FakePhysicsOptions::timestep, 1 ms by default: 1 kHz);
// - an IMU at a link (FakePhysicsOptions::imu_link): MuJoCo's framequat, gyro and accelerometer
//   sensors at a site on that link: orientation in the world, angular velocity and linear
//   acceleration (with gravity: +9.81 upwards at rest) in the link's frame;
// - a motor behind a transmission (FakePhysicsOptions::transmissions) in motor units, as the
//   fake robot's joint table (FakeJointSpec) has it: motor = gain * (joint - offset), the joint's
//   torque gain times the motor's (ros2_control's SimpleTransmission, gain = direction *
//   reduction). Coupled joints (a matrix mixing motors) are not simulated.
// After step(), the joints' positions and velocities are the integrated state; the IMU's readings
// are MuJoCo's sensors, computed before the last physics step's integration (1 ms older).
// A URDF MuJoCo cannot compile makes load() return false with one line naming the cause.
// Not simulated (yet): velocity limits (MuJoCo has none), coupled joints. A wheel's velocity
// servo is the transport's (zero kp, its kd towards the commanded velocity), as with
// FakeJointDynamics. step() allocates nothing (MuJoCo steps in the arena mj_makeData allocated).

#include <mujoco/mujoco.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "robot_hardware_interface/common/fake_joint_dynamics.hpp"
#include "robot_hardware_interface/common/fake_physics.hpp"

namespace robot_hardware_interface
{

// How far the robot's weight stretches a band of default stiffness [m].
inline constexpr double kBandSagDefault = 0.02;
// The physics steps at 1 kHz or faster [s].
inline constexpr double kLongestTimestep = 0.001;

template<size_t N>
class FakeMujocoPhysics final : public FakeJointEngine<N>
{
public:
  FakeMujocoPhysics(const FakeJointSpec * joints, size_t count)
  : joints_(joints), count_(count)
  {
    for (size_t k = 0; k < count_; ++k) {
      if (joints_[k].slot < N) {
        q_[joints_[k].slot] = joints_[k].initial_position;
      }
    }
  }

  ~FakeMujocoPhysics() override {unload();}
  FakeMujocoPhysics(const FakeMujocoPhysics &) = delete;
  FakeMujocoPhysics & operator=(const FakeMujocoPhysics &) = delete;

  // Compile the URDF and place the robot at its start pose. False with one line in *error when
  // MuJoCo cannot compile it or the joint table does not match it; *warnings gets one line per
  // thing the simulation leaves out (meshes not found, nothing to stand on). Not real-time.
  bool load(
    const FakePhysicsOptions & options, std::string * error, std::vector<std::string> * warnings)
  {
    unload();
    options_ = options;
    quiet_logging();
    if (!(options_.timestep > 0.0 && options_.timestep <= kLongestTimestep)) {
      char given[32];
      std::snprintf(given, sizeof(given), "%g", options_.timestep);
      *error = std::string("the physics timestep must be more than 0 and at most 0.001 s (1 kHz ") +
        "or faster), not " + given;
      return false;
    }
    if (!options_.armatures.empty() && options_.armatures.size() != count_) {
      *error = "armatures: " + std::to_string(options_.armatures.size()) + " values for " +
        std::to_string(count_) + " joints";
      return false;
    }
    if (!options_.transmissions.empty() && options_.transmissions.size() != count_) {
      *error = "transmissions: " + std::to_string(options_.transmissions.size()) +
        " values for " + std::to_string(count_) + " joints";
      return false;
    }
    gain_.assign(count_, 1.0);
    offset_.assign(count_, 0.0);
    for (size_t k = 0; k < options_.transmissions.size(); ++k) {
      const FakeTransmission & tr = options_.transmissions[k];
      if (!std::isfinite(tr.gain) || tr.gain == 0.0 || !std::isfinite(tr.offset)) {
        *error = std::string("joint '") + joints_[k].name + "': a transmission needs a finite, "
          "non-zero gain and a finite offset";
        return false;
      }
      gain_[k] = tr.gain;
      offset_[k] = tr.offset;
    }
    char parse_error[1024] = {0};
    mjSpec * spec = mj_parseXML(
      options_.urdf_path.c_str(), nullptr, parse_error, sizeof(parse_error));
    if (spec == nullptr) {
      *error = "MuJoCo cannot read " + options_.urdf_path + ": " + one_line(parse_error);
      return false;
    }
    // Compiled twice: once to measure the robot at its start pose (where its lowest point is,
    // how far it can reach), then with the floor where it belongs (a static geom stays where it
    // was compiled).
    bool built = edit(spec, error, warnings) && compile(spec, error) && bind(error);
    Extent extent{};
    if (built) {
      extent = measure();
      unload();
      add_floor(spec, extent);
      built = compile(spec, error) && bind(error) && start_pose(extent, warnings);
    }
    mj_deleteSpec(spec);
    if (!built) {
      unload();
    }
    return built;
  }

  bool loaded() const {return data_ != nullptr;}

  // A motor's new command, as FakeJointDynamics::command (FakeMotorCommands::set).
  void command(size_t slot, const FakeMotorCommand & c) {command_.set(slot, c);}
  void release() {command_.release();}

  // Advance the simulation by dt seconds, in physics steps of the options' timestep (the rest is
  // carried to the next call), the motor law recomputed before each.
  void step(double dt)
  {
    if (data_ == nullptr || !(dt > 0.0)) {
      return;
    }
    pending_ += dt;
    const double h = model_->opt.timestep;
    if (held_ && !gains_commanded()) {
      pending_ = 0.0;  // on its gantry: still, in its start pose
      read_state();
      at_rest_imu();
      return;
    }
    held_ = false;
    while (pending_ >= h * (1.0 - 1e-9)) {
      pending_ -= h;
      apply_forces();
      mj_step(model_, data_);
      ++physics_steps_;
      note_floor_touches();
    }
    read_state();
  }

  // As the engine of a FakeJointDynamics (use_engine): its commands in, the joints' state out.
  void advance(
    double dt, const std::array<FakeMotorCommand, N> & command, std::array<double, N> & q,
    std::array<double, N> & dq, std::array<double, N> & tau) override
  {
    command_.assign(command);
    step(dt);
    for (size_t k = 0; k < count_; ++k) {
      const size_t s = joints_[k].slot;
      if (s < N) {
        q[s] = q_[s];
        dq[s] = dq_[s];
        tau[s] = tau_[s];
      }
    }
  }

  // Put a joint at rest at `q` (clamped into its limits), as FakeJointDynamics::place.
  void place(size_t slot, double q) override
  {
    for (size_t k = 0; k < count_; ++k) {
      if (joints_[k].slot == slot && slot < N) {
        q = std::clamp(q, joints_[k].position_min, joints_[k].position_max);
        if (data_ != nullptr) {
          data_->qpos[qpos_adr_[k]] = joint_position(k, q);
          data_->qvel[dof_adr_[k]] = 0.0;
          mj_forward(model_, data_);
          read_state();
        } else {
          q_[slot] = q;
        }
        dq_[slot] = 0.0;
        tau_[slot] = 0.0;
      }
    }
  }

  // Let go of the band: the base is free from now on.
  void release_band() {band_on_ = false;}
  bool band_holding() const {return band_on_;}

  double position(size_t slot) const {return q_[slot];}
  double velocity(size_t slot) const {return dq_[slot];}
  double effort(size_t slot) const {return tau_[slot];}
  const FakeMotorCommand & last_command(size_t slot) const {return command_[slot];}
  uint64_t rejected_commands() const {return command_.rejected();}
  const FakeJointSpec * joints() const {return joints_;}
  size_t joint_count() const {return count_;}

  const FakeImuReading & imu() const {return imu_;}
  // The root link's origin in the world [m]: the free joint's position (current after step()),
  // or where a fixed base is welded.
  std::array<double, 3> base_position() const
  {
    std::array<double, 3> p{};
    if (data_ != nullptr) {
      const mjtNum * from = free_joint_ >= 0 ? data_->qpos + model_->jnt_qposadr[free_joint_] :
        data_->xpos + 3 * root_body_;
      for (int i = 0; i < 3; ++i) {
        p[i] = from[i];
      }
    }
    return p;
  }
  // The root link's orientation in the world (w, x, y, z).
  std::array<double, 4> base_orientation() const
  {
    std::array<double, 4> q{1.0, 0.0, 0.0, 0.0};
    if (data_ != nullptr) {
      const mjtNum * from = data_->xquat + 4 * root_body_;
      for (int i = 0; i < 4; ++i) {
        q[i] = from[i];
      }
    }
    return q;
  }
  double simulated_time() const {return data_ != nullptr ? data_->time : 0.0;}
  // The robot's mass as MuJoCo compiled it [kg] (every body's but the world's).
  double total_mass() const
  {
    double m = 0.0;
    for (int b = 1; model_ != nullptr && b < model_->nbody; ++b) {
      m += model_->body_mass[b];
    }
    return m;
  }
  // The links (compiled bodies: a link fixed to its parent is fused into it) that touched the floor
  // in any physics step since the last call, by name, and forget them. Not real-time.
  std::vector<std::string> floor_touches()
  {
    std::vector<std::string> names;
    for (size_t b = 0; b < touched_.size(); ++b) {
      if (touched_[b] != 0) {
        const char * name = mj_id2name(model_, mjOBJ_BODY, static_cast<int>(b));
        names.emplace_back(name != nullptr ? name : "body " + std::to_string(b));
        touched_[b] = 0;
      }
    }
    return names;
  }
  uint64_t physics_steps() const {return physics_steps_;}
  double band_stiffness() const {return band_k_;}
  double band_damping() const {return band_d_;}
  double floor_height() const {return floor_z_;}
  const mjModel * model() const {return model_;}
  const mjData * data() const {return data_;}

private:
  static constexpr int kFloorContype = 1;
  static constexpr int kRobotContype = 2;

  // MuJoCo's warnings (an unstable simulation, a full contact buffer) go to the console only,
  // never to MUJOCO_LOG.TXT in the working directory (MuJoCo's logging is process-wide).
  static void quiet_logging()
  {
    mjLogConfig config = mju_getLogConfig();
    config.logto_file = 0;
    mju_setLogConfig(config);
  }

  // MuJoCo's message on one line: its lines joined by "; ", without its "Error: " prefix and
  // without the note that the spec's static bodies were fused (the spec is thrown away).
  static std::string one_line(const char * text)
  {
    std::string line;
    std::string part;
    const auto flush = [&line, &part]() {
        const std::string prefix = "Error: ";
        if (part.compare(0, prefix.size(), prefix) == 0) {
          part.erase(0, prefix.size());
        }
        if (!part.empty() && part.compare(0, 17, "The static bodies") != 0) {
          line += (line.empty() ? "" : "; ") + part;
        }
        part.clear();
      };
    for (const char * c = text; c != nullptr && *c != '\0'; ++c) {
      if (*c == '\n' || *c == '\r') {
        flush();
      } else {
        part += *c;
      }
    }
    flush();
    return line.empty() ? std::string("no reason given") : line;
  }

  static mjsBody * root_of(mjSpec * spec, std::string * error)
  {
    mjsBody * world = mjs_findBody(spec, "world");
    mjsElement * first = world != nullptr ? mjs_firstChild(world, mjOBJ_BODY, 0) : nullptr;
    if (first == nullptr) {
      *error = "the URDF has no link";
      return nullptr;
    }
    if (mjs_nextChild(world, first, 0) != nullptr) {
      *error = "the URDF has more than one root link";
      return nullptr;
    }
    return mjs_asBody(first);
  }

  // Everything this simulation adds to the URDF, before compiling.
  bool edit(mjSpec * spec, std::string * error, std::vector<std::string> * warnings)
  {
    spec->option.timestep = options_.timestep;
    spec->option.integrator = mjINT_IMPLICITFAST;
    mjsBody * root = root_of(spec, error);
    if (root == nullptr) {
      return false;
    }
    root_name_ = mjs_getString(mjs_getName(root->element));
    root->fuse = 0;  // a fixed base's root link is static: kept a body, for base_position()
    // A floating joint the URDF already has (rare) is replaced by the chosen base.
    for (mjsElement * e = mjs_firstChild(root, mjOBJ_JOINT, 0); e != nullptr; ) {
      mjsElement * next = mjs_nextChild(root, e, 0);
      if (mjs_asJoint(e)->type == mjJNT_FREE) {
        mjs_delete(spec, e);
      }
      e = next;
    }
    if (options_.base != FakeBase::kFixed) {
      mjsJoint * free = mjs_addFreeJoint(root);
      mjs_setName(free->element, "rhi_floating_base");
    }
    for (size_t k = 0; k < count_; ++k) {
      mjsElement * e = mjs_findElement(spec, mjOBJ_JOINT, joints_[k].name);
      if (e == nullptr) {
        *error = std::string("joint '") + joints_[k].name + "' of the joint table is not a "
          "moving joint of the URDF as MuJoCo reads it";
        return false;
      }
      mjsJoint * joint = mjs_asJoint(e);
      joint->armature = options_.armatures.empty() ? joints_[k].armature : options_.armatures[k];
      set_linear(joint->damping, joints_[k].physics_damping);
      joint->frictionloss = joints_[k].frictionloss;
    }
    const std::string imu = options_.imu_link.empty() ? root_name_ : options_.imu_link;
    mjsBody * imu_body = mjs_findBody(spec, imu.c_str());
    if (imu_body == nullptr) {
      *error = "the IMU link '" + imu + "' is not a link of the URDF";
      return false;
    }
    mjsSite * site = mjs_addSite(imu_body, nullptr);
    mjs_setName(site->element, "rhi_imu");
    const mjtSensor kinds[3] = {mjSENS_FRAMEQUAT, mjSENS_GYRO, mjSENS_ACCELEROMETER};
    for (mjtSensor kind : kinds) {
      mjsSensor * sensor = mjs_addSensor(spec);
      sensor->type = kind;
      sensor->objtype = mjOBJ_SITE;
      mjs_setString(sensor->objname, "rhi_imu");
    }
    if (!resolve_meshes(spec, warnings)) {
      return false;
    }
    if (!options_.self_collision) {
      // Contact needs (contype1 & conaffinity2) || (contype2 & conaffinity1): the robot's geoms
      // (type 2, affinity 1) meet the floor's (type 1, affinity 2), never each other.
      for (mjsElement * e = mjs_firstElement(spec, mjOBJ_GEOM); e != nullptr;
        e = mjs_nextElement(spec, e))
      {
        mjsGeom * geom = mjs_asGeom(e);
        if (geom->contype != 0 || geom->conaffinity != 0) {
          geom->contype = kRobotContype;
          geom->conaffinity = kFloorContype;
        }
      }
    }
    return true;
  }

  // package:// and file:// into absolute paths; all or nothing (see the header comment).
  bool resolve_meshes(mjSpec * spec, std::vector<std::string> * warnings)
  {
    namespace fs = std::filesystem;
    const fs::path urdf_dir = fs::absolute(fs::path(options_.urdf_path)).parent_path();
    std::vector<std::pair<mjsMesh *, std::string>> found;
    size_t total = 0;
    std::string first_missing;
    for (mjsElement * e = mjs_firstElement(spec, mjOBJ_MESH); e != nullptr;
      e = mjs_nextElement(spec, e))
    {
      mjsMesh * mesh = mjs_asMesh(e);
      const std::string file = mjs_getString(mesh->file);
      ++total;
      const std::string path = resolve(file, urdf_dir);
      if (path.empty()) {
        if (first_missing.empty()) {
          first_missing = file;
        }
      } else {
        found.emplace_back(mesh, path);
      }
    }
    if (found.size() == total) {
      for (auto & f : found) {
        mjs_setString(f.first->file, f.second.c_str());
      }
      return true;
    }
    std::vector<mjsElement *> doomed;
    for (mjsElement * e = mjs_firstElement(spec, mjOBJ_GEOM); e != nullptr;
      e = mjs_nextElement(spec, e))
    {
      if (mjs_asGeom(e)->type == mjGEOM_MESH) {
        doomed.push_back(e);
      }
    }
    for (mjsElement * e = mjs_firstElement(spec, mjOBJ_MESH); e != nullptr;
      e = mjs_nextElement(spec, e))
    {
      doomed.push_back(e);
    }
    for (mjsElement * e : doomed) {
      mjs_delete(spec, e);
    }
    const std::string where = options_.package_path.empty() ?
      std::string("no package path given") :
      "package:// looked up under '" + options_.package_path + "'";
    std::string stand_in;
    if (!add_contacts(spec, &stand_in)) {
      warnings->push_back(stand_in);
      return false;
    }
    warnings->push_back(
      std::to_string(total - found.size()) + " of " + std::to_string(total) +
      " meshes not found (first: " + first_missing + "; " + where +
      "): the mesh geoms left out" + (stand_in.empty() ? std::string(", inertial-only model") :
      "; the vendor YAML's contacts stand in for them: " + stand_in));
    return true;
  }

  // The options' contacts on their links (in place of the mesh collisions left out). *what:
  // "2 on LINK_ANKLE_ROLL_L, ..." ("" when there are none); false with the reason in *what when
  // a contact names no link of the URDF.
  bool add_contacts(mjSpec * spec, std::string * what)
  {
    std::vector<std::pair<std::string, size_t>> per_link;
    for (const FakeContactGeom & c : options_.contacts) {
      mjsBody * body = mjs_findBody(spec, c.link);
      if (body == nullptr) {
        *what = std::string("contacts: '") + c.link + "' is not a link of the URDF";
        return false;
      }
      mjsGeom * geom = mjs_addGeom(body, nullptr);
      geom->type = c.shape == FakeContactShape::kBox ? mjGEOM_BOX :
        c.shape == FakeContactShape::kCylinder ? mjGEOM_CYLINDER : mjGEOM_SPHERE;
      // MuJoCo's sizes are half lengths: a box's half extents, a cylinder's radius and half length.
      geom->size[0] = c.shape == FakeContactShape::kBox ? 0.5 * c.size[0] : c.size[0];
      geom->size[1] = c.shape == FakeContactShape::kBox ? 0.5 * c.size[1] :
        c.shape == FakeContactShape::kCylinder ? 0.5 * c.size[1] : 0.0;
      geom->size[2] = c.shape == FakeContactShape::kBox ? 0.5 * c.size[2] : 0.0;
      for (int i = 0; i < 3; ++i) {
        geom->pos[i] = c.xyz[i];
      }
      rpy_to_quat(c.rpy, geom->quat);
      geom->mass = 0.0;  // a contact, not a body: the URDF's <inertial> stays the link's mass
      geom->density = 0.0;
      if (per_link.empty() || per_link.back().first != c.link) {
        per_link.emplace_back(c.link, 0);
      }
      ++per_link.back().second;
    }
    for (const auto & link : per_link) {
      *what += (what->empty() ? "" : ", ") + std::to_string(link.second) + " on " + link.first;
    }
    return true;
  }

  // URDF's rpy (rotations about the fixed x, y, z axes, in that order) as MuJoCo's w, x, y, z.
  static void rpy_to_quat(const std::array<double, 3> & rpy, double quat[4])
  {
    const double cr = std::cos(0.5 * rpy[0]), sr = std::sin(0.5 * rpy[0]);
    const double cp = std::cos(0.5 * rpy[1]), sp = std::sin(0.5 * rpy[1]);
    const double cy = std::cos(0.5 * rpy[2]), sy = std::sin(0.5 * rpy[2]);
    quat[0] = cr * cp * cy + sr * sp * sy;
    quat[1] = sr * cp * cy - cr * sp * sy;
    quat[2] = cr * sp * cy + sr * cp * sy;
    quat[3] = cr * cp * sy - sr * sp * cy;
  }

  // MuJoCo 3 has one damping coefficient per joint, MuJoCo 4 a polynomial (its first the linear).
  static void set_linear(double & field, double value) {field = value;}
  template<size_t K>
  static void set_linear(double (& field)[K], double value)
  {
    field[0] = value;
  }

  std::string resolve(const std::string & file, const std::filesystem::path & urdf_dir) const
  {
    namespace fs = std::filesystem;
    std::error_code ec;
    const std::string package = "package://";
    const std::string scheme = "file://";
    if (file.compare(0, package.size(), package) == 0) {
      const std::string rest = file.substr(package.size());
      const size_t slash = rest.find('/');
      if (slash == std::string::npos) {
        return "";
      }
      const std::string name = rest.substr(0, slash);
      const std::string inside = rest.substr(slash + 1);
      size_t begin = 0;
      while (begin <= options_.package_path.size()) {
        size_t end = options_.package_path.find(':', begin);
        if (end == std::string::npos) {
          end = options_.package_path.size();
        }
        const std::string prefix = options_.package_path.substr(begin, end - begin);
        begin = end + 1;
        if (prefix.empty()) {
          continue;
        }
        for (const fs::path & candidate :
          {fs::path(prefix) / "share" / name / inside, fs::path(prefix) / name / inside})
        {
          if (fs::is_regular_file(candidate, ec)) {
            return fs::absolute(candidate, ec).string();
          }
        }
      }
      return "";
    }
    fs::path path = file.compare(0, scheme.size(), scheme) == 0 ?
      fs::path(file.substr(scheme.size())) : fs::path(file);
    if (path.is_relative()) {
      path = urdf_dir / path;
    }
    return fs::is_regular_file(path, ec) ? path.string() : "";
  }

  // Addresses of the table's joints, the root link, the sensors.
  bool bind(std::string * error)
  {
    for (size_t k = 0; k < count_; ++k) {
      const int id = mj_name2id(model_, mjOBJ_JOINT, joints_[k].name);
      const int type = id >= 0 ? model_->jnt_type[id] : -1;
      if (type != mjJNT_HINGE && type != mjJNT_SLIDE) {
        *error = std::string("joint '") + joints_[k].name + "' is not a revolute or prismatic "
          "joint in MuJoCo's model of the URDF";
        return false;
      }
      qpos_adr_.push_back(model_->jnt_qposadr[id]);
      dof_adr_.push_back(model_->jnt_dofadr[id]);
    }
    root_body_ = mj_name2id(model_, mjOBJ_BODY, root_name_.c_str());
    if (root_body_ < 0) {
      *error = "the root link '" + root_name_ + "' is missing from the compiled model";
      return false;
    }
    free_joint_ = mj_name2id(model_, mjOBJ_JOINT, "rhi_floating_base");
    floor_geom_ = mj_name2id(model_, mjOBJ_GEOM, "rhi_floor");
    touched_.assign(static_cast<size_t>(model_->nbody), 0);
    if (model_->nsensor != 3 || (options_.base != FakeBase::kFixed && free_joint_ < 0)) {
      *error = "MuJoCo's model lacks the IMU sensors or the floating base it was given";
      return false;
    }
    return true;
  }

  bool compile(mjSpec * spec, std::string * error)
  {
    model_ = mj_compile(spec, nullptr);
    if (model_ == nullptr) {
      *error = "MuJoCo cannot compile " + options_.urdf_path + ": " + one_line(mjs_getError(spec));
      return false;
    }
    data_ = mj_makeData(model_);
    if (data_ == nullptr) {
      *error = "MuJoCo cannot allocate the simulation of " + options_.urdf_path;
      return false;
    }
    return true;
  }

  // The robot at its start pose, its root link where the URDF puts it.
  struct Extent
  {
    double lowest;     // [m] its lowest point: geoms' bounding boxes, else link origins
    double reach;      // [m] an upper bound of how far any point of it gets from its root link
    double root_z;     // [m] the root link's height
    int robot_geoms;   // geoms of the robot that collide (not the world's, not visuals)
  };

  void initial_joints()
  {
    mj_resetData(model_, data_);
    for (size_t k = 0; k < count_; ++k) {
      data_->qpos[qpos_adr_[k]] = joint_position(k, std::clamp(
          joints_[k].initial_position, joints_[k].position_min, joints_[k].position_max));
    }
    mj_forward(model_, data_);
  }

  Extent measure()
  {
    initial_joints();
    Extent e{INFINITY, 0.0, data_->xpos[3 * root_body_ + 2], 0};
    for (int b = 1; b < model_->nbody; ++b) {
      e.lowest = std::min(e.lowest, data_->xpos[3 * b + 2]);
      e.reach += norm3(model_->body_pos + 3 * b);
    }
    double largest_geom = 0.0;
    for (int g = 0; g < model_->ngeom; ++g) {
      if (model_->geom_bodyid[g] == 0) {
        continue;
      }
      largest_geom = std::max(
        largest_geom, model_->geom_rbound[g] + norm3(model_->geom_pos + 3 * g));
      if (model_->geom_contype[g] == 0 && model_->geom_conaffinity[g] == 0) {
        continue;  // a visual: it never touches the floor
      }
      ++e.robot_geoms;
      // The lowest corner of the geom's box in its own frame (geom_aabb: centre, half sizes),
      // turned into the world: a foot's sole sits on the floor, not its bounding sphere.
      const mjtNum * box = model_->geom_aabb + 6 * g;
      const mjtNum * r = data_->geom_xmat + 9 * g;
      double z = data_->geom_xpos[3 * g + 2];
      for (int i = 0; i < 3; ++i) {
        z += r[6 + i] * box[i] - std::fabs(r[6 + i]) * box[3 + i];
      }
      e.lowest = std::min(e.lowest, z);
    }
    e.reach += largest_geom;
    return e;
  }

  // A motor position of joint k of the table, as the joint's.
  double joint_position(size_t k, double motor) const {return motor / gain_[k] + offset_[k];}

  static double norm3(const mjtNum * v) {return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);}

  // The floor: z = 0 under a floating base; under a fixed one, below anything it can reach.
  void add_floor(mjSpec * spec, const Extent & extent)
  {
    floor_z_ = options_.base == FakeBase::kFixed ?
      std::min(0.0, extent.root_z - extent.reach - 0.1) : 0.0;
    mjsGeom * floor = mjs_addGeom(mjs_findBody(spec, "world"), nullptr);
    mjs_setName(floor->element, "rhi_floor");
    floor->type = mjGEOM_PLANE;
    floor->size[0] = 0.0;  // infinite
    floor->size[1] = 0.0;
    floor->size[2] = 0.05;
    floor->pos[2] = floor_z_;
    floor->contype = kFloorContype;
    floor->conaffinity = options_.self_collision ? kFloorContype : kRobotContype;
  }

  // The joints at their initial positions, the base where the options put it, the band's anchor.
  bool start_pose(const Extent & extent, std::vector<std::string> * warnings)
  {
    initial_joints();
    held_ = options_.base == FakeBase::kFree;
    if (options_.base != FakeBase::kFixed) {
      if (free_joint_ < 0) {
        return false;
      }
      // Lift the robot so that its lowest point is start_clearance above the floor.
      data_->qpos[model_->jnt_qposadr[free_joint_] + 2] +=
        floor_z_ + options_.start_clearance - extent.lowest;
      if (extent.robot_geoms == 0) {
        warnings->push_back(
          "the URDF has no collision geometry: nothing of the robot touches the floor, a free "
          "base falls through it");
      }
      mj_forward(model_, data_);
    }
    const double mass = model_->body_subtreemass[root_body_];
    const double g = norm3(model_->opt.gravity);
    band_k_ = options_.band_stiffness > 0.0 ? options_.band_stiffness :
      mass * g / kBandSagDefault;
    band_d_ = options_.band_damping > 0.0 ? options_.band_damping :
      2.0 * std::sqrt(band_k_ * mass);
    const double h = model_->opt.timestep;
    const mjtNum * inertia = model_->body_inertia + 3 * root_body_;
    const double smallest = std::min({inertia[0], inertia[1], inertia[2]});
    band_d_ = std::min(band_d_, 0.25 * model_->body_mass[root_body_] / h);
    band_turn_d_ = std::min(band_d_ * options_.band_arm * options_.band_arm, 0.25 * smallest / h);
    // The band's point: above the centre of mass, kept in the root link's frame.
    const mjtNum * origin = data_->xpos + 3 * root_body_;
    const mjtNum * com = data_->subtree_com + 3 * root_body_;
    const mjtNum point[3] = {com[0], com[1], com[2] + options_.band_arm};
    const mjtNum offset[3] = {point[0] - origin[0], point[1] - origin[1], point[2] - origin[2]};
    mjtNum inverse[4];
    mju_negQuat(inverse, data_->xquat + 4 * root_body_);
    mju_rotVecQuat(band_point_local_.data(), offset, inverse);
    for (int i = 0; i < 3; ++i) {
      band_anchor_[i] = point[i];
    }
    band_anchor_[2] += band_k_ > 0.0 ? mass * g / band_k_ : 0.0;
    band_on_ = options_.base == FakeBase::kBand;
    read_state();
    if (held_) {
      at_rest_imu();
    }
    return true;
  }

  void apply_forces()
  {
    mju_zero(data_->qfrc_applied, model_->nv);
    for (size_t k = 0; k < count_; ++k) {
      const FakeJointSpec & j = joints_[k];
      if (j.slot >= N) {
        continue;
      }
      const FakeMotorCommand & c = command_[j.slot];
      // In motor units, as the motor board sees it; the joint gets gain times the torque.
      const double q = gain_[k] * (data_->qpos[qpos_adr_[k]] - offset_[k]);
      const double dq = gain_[k] * data_->qvel[dof_adr_[k]];
      double tau = c.kp * (c.q - q) + c.kd * (c.dq - dq) + c.tau_ff;
      tau = std::clamp(tau, -j.effort_max, j.effort_max);
      data_->qfrc_applied[dof_adr_[k]] = gain_[k] * tau;
      tau_[j.slot] = tau;
    }
    mjtNum * wrench = data_->xfrc_applied + 6 * root_body_;
    for (int i = 0; i < 6; ++i) {
      wrench[i] = 0.0;
    }
    if (band_on_ && free_joint_ >= 0) {
      // The band's point and its velocity from the free joint's current state (position, quat;
      // linear velocity in the world, angular velocity in the link's frame).
      const mjtNum * pos = data_->qpos + model_->jnt_qposadr[free_joint_];
      const mjtNum * quat = pos + 3;
      const mjtNum * vel = data_->qvel + model_->jnt_dofadr[free_joint_];
      mjtNum arm[3], omega[3], com[3];
      mju_rotVecQuat(arm, band_point_local_.data(), quat);
      mju_rotVecQuat(omega, vel + 3, quat);
      mju_rotVecQuat(com, model_->body_ipos + 3 * root_body_, quat);
      // The spring pulls at the band's point (its moment keeps the robot upright); the damping
      // is split into a force at the link's centre of mass and a torque, each bounded to what an
      // explicit force on that one link can take at this timestep (the band is no constraint).
      mjtNum spring[3], lever[3];
      for (int i = 0; i < 3; ++i) {
        spring[i] = band_k_ * (band_anchor_[i] - (pos[i] + arm[i]));
        lever[i] = arm[i] - com[i];  // from the link's centre of mass to the band's point
      }
      mju_cross(wrench + 3, lever, spring);
      mjtNum com_velocity[3];
      mju_cross(com_velocity, omega, com);
      for (int i = 0; i < 3; ++i) {
        wrench[i] = spring[i] - band_d_ * (vel[i] + com_velocity[i]);
        wrench[3 + i] -= band_turn_d_ * omega[i];
      }
    }
  }

  // The IMU of a robot held still: no rotation, gravity's reaction (up) in the IMU link's frame.
  void at_rest_imu()
  {
    const mjtNum up[3] = {0.0, 0.0, norm3(model_->opt.gravity)};
    mjtNum inverse[4];
    mju_negQuat(inverse, imu_.orientation.data());
    mjtNum in_link[3];
    mju_rotVecQuat(in_link, up, inverse);
    for (int i = 0; i < 3; ++i) {
      imu_.angular_velocity[i] = 0.0;
      imu_.linear_acceleration[i] = in_link[i];
    }
  }

  // Whether any motor has been told a gain (stiffness or damping).
  bool gains_commanded() const
  {
    for (size_t k = 0; k < count_; ++k) {
      const size_t s = joints_[k].slot;
      if (s < N && (command_[s].kp > 0.0 || command_[s].kd > 0.0)) {
        return true;
      }
    }
    return false;
  }

  // Which bodies the floor's contacts touch (allocation-free: touched_ is sized at load()).
  void note_floor_touches()
  {
    for (int i = 0; i < data_->ncon; ++i) {
      const mjContact & c = data_->contact[i];
      const int other = c.geom[0] == floor_geom_ ? c.geom[1] :
        c.geom[1] == floor_geom_ ? c.geom[0] : -1;
      if (other >= 0) {
        touched_[static_cast<size_t>(model_->geom_bodyid[other])] = 1;
      }
    }
  }

  void read_state()
  {
    for (size_t k = 0; k < count_; ++k) {
      const size_t s = joints_[k].slot;
      if (s < N) {
        q_[s] = gain_[k] * (data_->qpos[qpos_adr_[k]] - offset_[k]);
        dq_[s] = gain_[k] * data_->qvel[dof_adr_[k]];
      }
    }
    const mjtNum * quat = data_->sensordata + model_->sensor_adr[0];
    const mjtNum * gyro = data_->sensordata + model_->sensor_adr[1];
    const mjtNum * acc = data_->sensordata + model_->sensor_adr[2];
    for (int i = 0; i < 4; ++i) {
      imu_.orientation[i] = quat[i];
    }
    for (int i = 0; i < 3; ++i) {
      imu_.angular_velocity[i] = gyro[i];
      imu_.linear_acceleration[i] = acc[i];
    }
  }

  void unload()
  {
    if (data_ != nullptr) {
      mj_deleteData(data_);
      data_ = nullptr;
    }
    if (model_ != nullptr) {
      mj_deleteModel(model_);
      model_ = nullptr;
    }
    qpos_adr_.clear();
    dof_adr_.clear();
    pending_ = 0.0;
  }

  const FakeJointSpec * joints_;
  size_t count_;
  FakePhysicsOptions options_;
  mjModel * model_{nullptr};
  mjData * data_{nullptr};
  std::vector<int> qpos_adr_;  // per joint of the table
  std::vector<int> dof_adr_;
  std::vector<double> gain_;   // per joint of the table: motor = gain * (joint - offset)
  std::vector<double> offset_;
  std::string root_name_;
  int root_body_{-1};
  int free_joint_{-1};
  int floor_geom_{-1};
  bool held_{false};  // a free base in its start pose until the first gains (the header comment)
  std::vector<char> touched_;  // per body: touched the floor since floor_touches()
  double floor_z_{0.0};
  double band_k_{0.0};
  double band_d_{0.0};
  double band_turn_d_{0.0};  // [N m s / rad] the band's damping of the root link's rotation
  std::array<double, 3> band_anchor_{};
  std::array<mjtNum, 3> band_point_local_{};  // the band's point in the root link's frame
  bool band_on_{false};
  double pending_{0.0};
  uint64_t physics_steps_{0};
  std::array<double, N> q_{};
  std::array<double, N> dq_{};
  std::array<double, N> tau_{};
  FakeMotorCommands<N> command_;
  FakeImuReading imu_;
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__COMMON__FAKE_PHYSICS_MUJOCO_HPP_
