#include "game/bench/bullet_baseline.hpp"

#include <cmath>
#include <memory>

#include <btBulletDynamicsCommon.h>

namespace sweetspot::bench {
namespace {

btVector3 bt(const Vec3& v) { return btVector3(v.x(), v.y(), v.z()); }
Vec3 eig(const btVector3& v) { return Vec3(v.x(), v.y(), v.z()); }

struct TickContext {
  btRigidBody* ball = nullptr;
  const AeroFn* aero = nullptr;
  btDiscreteDynamicsWorld* world = nullptr;
  Vec3 launch_position = Vec3::Zero();
  BaselineResult* result = nullptr;
  double substep_dt = 0.0;
  bool airborne = false;  // a ball teed up touches the ground at launch; landing needs a lift-off first
};

void pre_tick(btDynamicsWorld* world, btScalar dt) {
  auto* ctx = static_cast<TickContext*>(world->getWorldUserInfo());
  btRigidBody* b = ctx->ball;
  const Vec3 p = eig(b->getCenterOfMassPosition());
  const Vec3 v = eig(b->getLinearVelocity());
  const Vec3 w = eig(b->getAngularVelocity());
  const AeroEffect fx = (*ctx->aero)(p, v, w);
  // Bullet accumulates forces until the end of stepSimulation(); clear and re-apply so
  // each substep sees exactly gravity + this substep's aero force.
  b->clearForces();
  b->applyGravity();
  b->applyCentralForce(bt(fx.force));
  b->setAngularVelocity(bt(w + fx.spin_rate * dt));
}

void post_tick(btDynamicsWorld* world, btScalar /*dt*/) {
  auto* ctx = static_cast<TickContext*>(world->getWorldUserInfo());
  ++ctx->result->substeps;
  if (ctx->result->landed) return;
  bool touching = false;
  btDispatcher* d = world->getDispatcher();
  for (int i = 0; i < d->getNumManifolds() && !touching; ++i) {
    const btPersistentManifold* m = d->getManifoldByIndexInternal(i);
    for (int c = 0; c < m->getNumContacts(); ++c) {
      if (m->getContactPoint(c).getDistance() <= 0.0) {
        touching = true;
        break;
      }
    }
  }
  if (!touching) {
    ctx->airborne = true;
  } else if (ctx->airborne) {
    const Vec3 p = eig(ctx->ball->getCenterOfMassPosition()) - ctx->launch_position;
    ctx->result->carry_m = std::hypot(p.x(), p.z());
    ctx->result->landed = true;
  }
}

}  // namespace

BaselineGroundShape::BaselineGroundShape(const BaselineGround& ground) : ground_(ground) {
  auto* mesh = new btTriangleMesh(true, false);
  for (size_t i = 0; i + 2 < ground.indices.size(); i += 3) {
    mesh->addTriangle(bt(ground.positions[static_cast<size_t>(ground.indices[i])]),
                      bt(ground.positions[static_cast<size_t>(ground.indices[i + 1])]),
                      bt(ground.positions[static_cast<size_t>(ground.indices[i + 2])]));
  }
  mesh_ = mesh;
  shape_ = new btBvhTriangleMeshShape(mesh, true);
}

BaselineGroundShape::~BaselineGroundShape() {
  delete static_cast<btBvhTriangleMeshShape*>(shape_);
  delete static_cast<btTriangleMesh*>(mesh_);
}

BaselineResult run_bullet_baseline(const LaunchState& launch, const BaselineBall& ball,
                                   const AeroFn& aero, const BaselineGround& ground,
                                   const BaselineOptions& options) {
  const BaselineGroundShape shape(ground);
  return run_bullet_baseline(launch, ball, aero, shape, options);
}

BaselineResult run_bullet_baseline(const LaunchState& launch, const BaselineBall& ball,
                                   const AeroFn& aero, const BaselineGroundShape& ground_shape,
                                   const BaselineOptions& options) {
  const BaselineGround& ground = ground_shape.ground();
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher(&config);
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &config);
  world.setGravity(btVector3(0, -kGravity, 0));

  auto* ground_bvh = static_cast<btBvhTriangleMeshShape*>(ground_shape.shape());
  btRigidBody::btRigidBodyConstructionInfo ground_info(0.0, nullptr, ground_bvh);
  ground_info.m_restitution = ground.restitution;
  ground_info.m_friction = ground.friction;
  ground_info.m_rollingFriction = ground.rolling_friction;
  btRigidBody ground_body(ground_info);
  world.addRigidBody(&ground_body);

  btSphereShape sphere(ball.radius);
  btTransform start;
  start.setIdentity();
  start.setOrigin(bt(launch.position));
  btDefaultMotionState motion(start);
  btRigidBody::btRigidBodyConstructionInfo info(ball.mass, &motion, &sphere,
                                                btVector3(ball.inertia, ball.inertia, ball.inertia));
  info.m_restitution = 1.0;  // the pair's restitution is ball × ground = ground's value
  info.m_friction = 1.0;
  info.m_rollingFriction = 1.0;
  info.m_linearDamping = 0.0;
  info.m_angularDamping = 0.0;
  btRigidBody body(info);
  body.setLinearVelocity(bt(launch.velocity));
  body.setAngularVelocity(bt(launch.spin));
  body.setActivationState(DISABLE_DEACTIVATION);
  // Continuous collision detection, as any game does for a small fast ball.
  body.setCcdMotionThreshold(ball.radius * 0.5);
  body.setCcdSweptSphereRadius(ball.radius * 0.9);
  world.addRigidBody(&body);

  BaselineResult result;
  TickContext ctx{&body, &aero, &world, launch.position, &result, options.substep_dt};
  world.setInternalTickCallback(pre_tick, &ctx, true);
  world.setInternalTickCallback(post_tick, &ctx, false);
  // setInternalTickCallback stores one user pointer shared by both callbacks.
  world.setWorldUserInfo(&ctx);

  const int max_substeps = static_cast<int>(std::ceil(options.frame_dt / options.substep_dt)) + 1;
  double t = 0.0;
  while (t < options.max_time) {
    world.stepSimulation(options.frame_dt, max_substeps, options.substep_dt);
    t += options.frame_dt;
    if (result.landed && options.carry_only) break;
    if (result.landed && body.getLinearVelocity().length() < options.rest_speed) break;
  }
  const Vec3 p = eig(body.getCenterOfMassPosition()) - launch.position;
  result.total_m = std::hypot(p.x(), p.z());
  result.time_s = t;
  world.removeRigidBody(&body);
  world.removeRigidBody(&ground_body);
  return result;
}

}  // namespace sweetspot::bench
