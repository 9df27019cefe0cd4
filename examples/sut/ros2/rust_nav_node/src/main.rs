// SPDX-License-Identifier: EPL-2.0
//! A ROS 2 navigation node on ros2-client (RustDDS, not REI's Cyclone DDS): an independent ROS 2 implementation
//! as the system under test of REI's ROS 2 bridge (docs/ros.md).
//!
//!     rei run CASE --sut "ros2:PATH/TO/rei-ros2-nav-node" --sut-map
//!
//! It subscribes /clock, /odom, /tf, /scan and /map, publishes /cmd_vel once per new /clock (zero while idle),
//! and serves nav2's NavigateToPose with ros2-client's own high-level action server (`AsyncActionServer`, which
//! publishes a goal's final status only once the client has asked for its result). Navigation is plain: turn
//! towards the goal, then drive, holding while the laser sees something close ahead. Services use
//! rmw_cyclonedds's request/reply mapping (`ServiceMapping::Cyclone`), the one REI's bridge speaks.
//!
//! `--never-answer`: serve the action but never take a goal (a stack that hangs; the bridge must end the run).
//! The domain is `ROS_DOMAIN_ID` (default 0), as the bridge sets it.

use std::{f64::consts::PI, time::Duration};

use futures::{stream, FutureExt as _, StreamExt};
use ros2_client::{
  action::{ActionServerQosPolicies, AsyncActionServer, ExecutingGoalHandle, GoalEndStatus},
  qos::{Durability, History},
  ActionTypeName, Context, ContextOptions, Message, MessageTypeName, Name, Node, NodeName, NodeOptions, QosProfile,
  ServiceMapping,
};
use serde::{Deserialize, Serialize};
use smol::future::FutureExt as _;

// -- the ROS messages, field for field (ros2-client serializes them as CDR, in field order) ---------------------

#[derive(Clone, Copy, Debug, Default, Serialize, Deserialize)]
struct Time {
  sec: i32,
  nanosec: u32,
}
impl Time {
  fn nanos(&self) -> i64 {
    self.sec as i64 * 1_000_000_000 + self.nanosec as i64
  }
}

#[derive(Clone, Debug, Default, Serialize, Deserialize)]
struct Header {
  stamp: Time,
  frame_id: String,
}

#[derive(Clone, Copy, Debug, Default, Serialize, Deserialize)]
struct Vector3 {
  x: f64,
  y: f64,
  z: f64,
}

#[derive(Clone, Copy, Debug, Default, Serialize, Deserialize)]
struct Quaternion {
  x: f64,
  y: f64,
  z: f64,
  w: f64,
}
impl Quaternion {
  fn yaw(&self) -> f64 {
    (2.0 * (self.w * self.z + self.x * self.y)).atan2(1.0 - 2.0 * (self.y * self.y + self.z * self.z))
  }
}

#[derive(Clone, Copy, Debug, Default, Serialize, Deserialize)]
struct Pose {
  position: Vector3, // geometry_msgs/Point: the same three float64
  orientation: Quaternion,
}

/// float64[36]: serde's arrays stop at 32 elements; a tuple of arrays is the same 36 doubles in CDR.
type Covariance = ([f64; 32], [f64; 4]);

#[derive(Clone, Debug, Serialize, Deserialize)]
struct PoseWithCovariance {
  pose: Pose,
  covariance: Covariance,
}

#[derive(Clone, Copy, Debug, Default, Serialize, Deserialize)]
struct Twist {
  linear: Vector3,
  angular: Vector3,
}
impl Message for Twist {}

#[derive(Clone, Debug, Serialize, Deserialize)]
struct TwistWithCovariance {
  twist: Twist,
  covariance: Covariance,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
struct Odometry {
  header: Header,
  child_frame_id: String,
  pose: PoseWithCovariance,
  twist: TwistWithCovariance,
}
impl Message for Odometry {}

#[derive(Clone, Debug, Serialize, Deserialize)]
struct Transform {
  translation: Vector3,
  rotation: Quaternion,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
struct TransformStamped {
  header: Header,
  child_frame_id: String,
  transform: Transform,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
struct TFMessage {
  transforms: Vec<TransformStamped>,
}
impl Message for TFMessage {}

#[derive(Clone, Debug, Serialize, Deserialize)]
struct LaserScan {
  header: Header,
  angle_min: f32,
  angle_max: f32,
  angle_increment: f32,
  time_increment: f32,
  scan_time: f32,
  range_min: f32,
  range_max: f32,
  ranges: Vec<f32>,
  intensities: Vec<f32>,
}
impl Message for LaserScan {}

#[derive(Clone, Debug, Serialize, Deserialize)]
struct MapMetaData {
  map_load_time: Time,
  resolution: f32,
  width: u32,
  height: u32,
  origin: Pose,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
struct OccupancyGrid {
  header: Header,
  info: MapMetaData,
  data: Vec<i8>,
}
impl Message for OccupancyGrid {}

#[derive(Clone, Debug, Serialize, Deserialize)]
struct Clock {
  clock: Time,
}
impl Message for Clock {}

#[derive(Clone, Debug, Default, Serialize, Deserialize)]
struct PoseStamped {
  header: Header,
  pose: Pose,
}

/// nav2_msgs/action/NavigateToPose's goal.
#[derive(Clone, Debug, Serialize, Deserialize)]
struct NavigateToPoseGoal {
  pose: PoseStamped,
  behavior_tree: String,
}
impl Message for NavigateToPoseGoal {}

/// Its result as of Jazzy (Humble's is std_msgs/Empty); REI reads only the status before it.
#[derive(Clone, Debug, Serialize, Deserialize)]
struct NavigateToPoseResult {
  error_code: u16,
  error_msg: String,
}
impl Message for NavigateToPoseResult {}

#[derive(Clone, Copy, Debug, Default, Serialize, Deserialize)]
struct RosDuration {
  sec: i32,
  nanosec: u32,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
struct NavigateToPoseFeedback {
  current_pose: PoseStamped,
  navigation_time: RosDuration,
  estimated_time_remaining: RosDuration,
  number_of_recoveries: i16,
  distance_remaining: f32,
}
impl Message for NavigateToPoseFeedback {}

// -- navigation ----------------------------------------------------------------------------------------------

const MAX_LINEAR: f64 = 0.26; // a TurtleBot3 Waffle's limits
const MAX_ANGULAR: f64 = 1.5;
const REACHED: f64 = 0.1; // metres: well inside REI's goal tolerance
const HEADING: f64 = 0.3; // radians off the goal's bearing: turn on the spot beyond it
const CLEARANCE: f64 = 0.45; // metres of free laser range ahead needed to drive
const AHEAD: f64 = 0.5; // radians either side of straight ahead

#[derive(Clone, Copy, Debug)]
struct Pose2D {
  x: f64,
  y: f64,
  yaw: f64,
}

fn wrap(angle: f64) -> f64 {
  (angle + PI).rem_euclid(2.0 * PI) - PI
}

/// `a` then `b`: `b` expressed in `a`'s frame, composed (map->odom with odom->base_link).
fn compose(a: Pose2D, b: Pose2D) -> Pose2D {
  let (s, c) = a.yaw.sin_cos();
  Pose2D {
    x: a.x + c * b.x - s * b.y,
    y: a.y + s * b.x + c * b.y,
    yaw: wrap(a.yaw + b.yaw),
  }
}

fn pose2d(position: Vector3, orientation: Quaternion) -> Pose2D {
  Pose2D {
    x: position.x,
    y: position.y,
    yaw: orientation.yaw(),
  }
}

/// The nearest laser return within AHEAD of straight ahead (infinity when none).
fn nearest_ahead(scan: &LaserScan) -> f64 {
  scan
    .ranges
    .iter()
    .enumerate()
    .filter(|(i, _)| ((scan.angle_min + *i as f32 * scan.angle_increment) as f64).abs() <= AHEAD)
    .map(|(_, r)| *r as f64)
    .filter(|r| r.is_finite() && *r >= scan.range_min as f64)
    .fold(f64::INFINITY, f64::min)
}

/// The command towards `goal` from `pose`, and whether the goal is reached.
fn steer(pose: Pose2D, goal: Pose2D, nearest: f64) -> (Twist, bool) {
  let (dx, dy) = (goal.x - pose.x, goal.y - pose.y);
  let distance = dx.hypot(dy);
  if distance < REACHED {
    return (Twist::default(), true);
  }
  let error = wrap(dy.atan2(dx) - pose.yaw);
  let w = (2.0 * error).clamp(-MAX_ANGULAR, MAX_ANGULAR);
  let v = if error.abs() > HEADING || nearest < CLEARANCE {
    0.0
  } else {
    (0.8 * distance).min(MAX_LINEAR) * error.cos()
  };
  (
    Twist {
      linear: Vector3 {
        x: v,
        ..Default::default()
      },
      angular: Vector3 {
        z: w,
        ..Default::default()
      },
    },
    false,
  )
}

// -- the node ------------------------------------------------------------------------------------------------

type NavServer = AsyncActionServer<NavigateToPoseGoal, NavigateToPoseResult, NavigateToPoseFeedback>;

struct Goal {
  handle: ExecutingGoalHandle<NavigateToPoseGoal>,
  target: Pose2D,
  started: i64,
}

fn main() {
  let never_answer = std::env::args().any(|a| a == "--never-answer");
  let domain: u16 = std::env::var("ROS_DOMAIN_ID")
    .ok()
    .and_then(|d| d.parse().ok())
    .unwrap_or(0);
  let context = Context::with_options(ContextOptions::new().domain_id(domain)).expect("DDS participant");
  let mut node = context
    .new_node(
      NodeName::new("/", "rei_rust_nav").unwrap(),
      NodeOptions::new().enable_rosout(false),
    )
    .expect("ROS 2 node");
  let mode = if never_answer { ", never answering goals" } else { "" };
  println!(
    "ros2-client navigation node, pid {}, on ROS domain {domain}{mode}",
    std::process::id()
  );
  smol::block_on(run(&mut node, never_answer));
}

fn topic(node: &Node, name: &str, package: &str, kind: &str, qos: &QosProfile) -> ros2_client::dds::rustdds::Topic {
  node
    .create_topic(&Name::new("/", name).unwrap(), MessageTypeName::new(package, kind), qos)
    .unwrap()
}

async fn run(node: &mut Node, never_answer: bool) {
  // rmw_qos_profile_default (reliable, volatile, keep-last 10), as the bridge publishes; /map transient-local
  let reliable = QosProfile::publisher_default().history(History::KeepLast { depth: 10 });
  let latched = QosProfile::publisher_default()
    .history(History::KeepLast { depth: 1 })
    .durability(Durability::TransientLocal);
  let clock_topic = topic(node, "clock", "rosgraph_msgs", "Clock", &reliable);
  let odom_topic = topic(node, "odom", "nav_msgs", "Odometry", &reliable);
  let tf_topic = topic(node, "tf", "tf2_msgs", "TFMessage", &reliable);
  let scan_topic = topic(node, "scan", "sensor_msgs", "LaserScan", &reliable);
  let map_topic = topic(node, "map", "nav_msgs", "OccupancyGrid", &latched);
  let cmd_topic = topic(node, "cmd_vel", "geometry_msgs", "Twist", &reliable);
  let clock_sub = node
    .create_subscription::<Clock>(&clock_topic, Some(reliable.clone()))
    .unwrap();
  let odom_sub = node
    .create_subscription::<Odometry>(&odom_topic, Some(reliable.clone()))
    .unwrap();
  let tf_sub = node
    .create_subscription::<TFMessage>(&tf_topic, Some(reliable.clone()))
    .unwrap();
  let scan_sub = node
    .create_subscription::<LaserScan>(&scan_topic, Some(reliable.clone()))
    .unwrap();
  let map_sub = node
    .create_subscription::<OccupancyGrid>(&map_topic, Some(latched.clone()))
    .unwrap();
  let cmd_vel = node
    .create_publisher::<Twist>(&cmd_topic, Some(reliable.clone()))
    .unwrap();

  // rcl_action's defaults: services and feedback volatile, status transient-local keep-last 1
  let service = QosProfile::publisher_default().history(History::KeepLast { depth: 10 });
  let status = QosProfile::publisher_default()
    .history(History::KeepLast { depth: 1 })
    .durability(Durability::TransientLocal);
  let server: NavServer = AsyncActionServer::new(
    node
      .create_action_server(
        ServiceMapping::Cyclone,
        &Name::new("/", "navigate_to_pose").unwrap(),
        &ActionTypeName::new("nav2_msgs", "NavigateToPose"),
        ActionServerQosPolicies {
          goal_service: service.clone(),
          result_service: service.clone(),
          cancel_service: service.clone(),
          feedback_publisher: service,
          status_publisher: status,
        },
      )
      .unwrap(),
  );

  let mut clocks = Box::pin(clock_sub.async_stream());
  let mut odoms = Box::pin(odom_sub.async_stream());
  let mut tfs = Box::pin(tf_sub.async_stream());
  let mut scans = Box::pin(scan_sub.async_stream());
  let mut maps = Box::pin(map_sub.async_stream());
  let mut goals = Box::pin(
    stream::unfold(&server, |server| async move {
      if never_answer {
        futures::future::pending::<()>().await;
      }
      Some((server.receive_new_goal().await, server))
    })
    .fuse(),
  );
  let mut cancels = Box::pin(
    stream::unfold(&server, |server| async move {
      Some((server.receive_cancel_request().await, server))
    })
    .fuse(),
  );

  let mut odom: Option<Pose2D> = None;
  let mut map_to_odom = Pose2D {
    x: 0.0,
    y: 0.0,
    yaw: 0.0,
  };
  let mut nearest = f64::INFINITY;
  let mut last_clock = i64::MIN;
  let mut goal: Option<Goal> = None;
  let mut steps = 0u64;
  loop {
    let mut ended: Option<GoalEndStatus> = None;
    futures::select! {
      message = clocks.select_next_some() => {
        let Ok((clock, _)) = message else { continue };
        let now = clock.clock.nanos();
        if now <= last_clock {
          continue; // the repeated start clock: one command per new time
        }
        last_clock = now;
        let mut command = Twist::default();
        if let (Some(active), Some(odom)) = (goal.as_ref(), odom) {
          let pose = compose(map_to_odom, odom);
          let (twist, reached) = steer(pose, active.target, nearest);
          command = twist;
          if reached {
            ended = Some(GoalEndStatus::Succeeded);
          } else if steps.is_multiple_of(10) {
            let feedback = NavigateToPoseFeedback {
              current_pose: PoseStamped::default(),
              navigation_time: RosDuration { sec: ((now - active.started) / 1_000_000_000) as i32, nanosec: 0 },
              estimated_time_remaining: RosDuration::default(),
              number_of_recoveries: 0,
              distance_remaining: (active.target.x - pose.x).hypot(active.target.y - pose.y) as f32,
            };
            let _ = server.publish_feedback(active.handle.clone(), feedback).await;
          }
          steps += 1;
        }
        if cmd_vel.publish(command).is_err() {
          eprintln!("cmd_vel not sent");
        }
      }
      message = odoms.select_next_some() => {
        if let Ok((o, _)) = message {
          odom = Some(pose2d(o.pose.pose.position, o.pose.pose.orientation));
        }
      }
      message = tfs.select_next_some() => {
        if let Ok((tf, _)) = message {
          for edge in tf.transforms.iter().filter(|e| e.header.frame_id == "map" && e.child_frame_id == "odom") {
            map_to_odom = pose2d(edge.transform.translation, edge.transform.rotation);
          }
        }
      }
      message = scans.select_next_some() => {
        if let Ok((scan, _)) = message {
          nearest = nearest_ahead(&scan);
        }
      }
      message = maps.select_next_some() => {
        if let Ok((grid, _)) = message {
          println!("map {}x{} cells at {} m", grid.info.width, grid.info.height, grid.info.resolution);
        }
      }
      new_goal = goals.select_next_some() => {
        let Ok(new_goal) = new_goal else { continue };
        let target = server.get_new_goal(new_goal.clone()).map(|g| pose2d(g.pose.pose.position, g.pose.pose.orientation));
        match target {
          Some(target) if goal.is_none() => {
            // a DDS error here is the node's to report, not to die of: the client then says the goal went unanswered
            let accepted = match server.accept_goal(new_goal).await {
              Ok(accepted) => accepted,
              Err(error) => {
                println!("goal ({:.2}, {:.2}) not accepted: {error:?}", target.x, target.y);
                continue;
              }
            };
            match server.start_executing_goal(accepted).await {
              Ok(handle) => {
                println!("goal ({:.2}, {:.2}) accepted", target.x, target.y);
                goal = Some(Goal { handle, target, started: last_clock });
              }
              Err(error) => println!("goal ({:.2}, {:.2}) accepted, not started: {error:?}", target.x, target.y),
            }
          }
          _ => {
            println!("goal rejected: one is running");
            let _ = server.reject_goal(new_goal).await;
          }
        }
      }
      cancel = cancels.select_next_some() => {
        let Ok(cancel) = cancel else { continue };
        match goal.as_ref().map(|g| g.handle.goal_id()) {
          Some(id) if cancel.contains_goal(&id) => {
            let _ = server.respond_to_cancel_requests(&cancel, std::iter::once(id)).await;
            ended = Some(GoalEndStatus::Canceled);
          }
          _ => {
            let _ = server.respond_to_cancel_requests(&cancel, std::iter::empty()).await;
          }
        }
      }
    }
    if let Some(status) = ended {
      let active = goal.take().expect("an active goal");
      let _ = cmd_vel.publish(Twist::default());
      // resolves once the client has asked for the result (REI does as soon as the goal is accepted)
      let result = NavigateToPoseResult {
        error_code: 0,
        error_msg: String::new(),
      };
      let sent = server
        .send_result_response(active.handle, status, result)
        .map(Some)
        .or(async {
          smol::Timer::after(Duration::from_secs(5)).await;
          None
        })
        .await;
      match sent {
        Some(Ok(())) => println!("goal ended: {status:?}"),
        Some(Err(error)) => println!("goal ended: {status:?}; result not sent: {error:?}"),
        None => println!("goal ended: {status:?}; no client asked for its result within 5 s"),
      }
    }
  }
}
