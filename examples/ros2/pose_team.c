/* One robot of a ROS 2 team over sanet's simulated radio: the worked example of docs/ros2.md
 * ("A worked example: a team over the simulated radio"). Plain C on Cyclone DDS, speaking ROS 2's
 * topics, types and QoS, so that it runs where ROS 2 is not installed; a ROS 2 user would write
 * the same with rclcpp or rclpy.
 *
 * In the ROS 2 face's domain (--face-domain, 0; Cyclone on sim0, the link to the simulator):
 *   reads  /ROBOT/ground_truth  nav_msgs/msg/Odometry    the robot's pose in the world
 *   writes /ROBOT/cmd_vel       geometry_msgs/msg/Twist
 * In the team's domain (--team-domain, 1; Cyclone on radio0, the simulated radio):
 *   writes /ROBOT/pose          geometry_msgs/msg/PoseStamped, 5 Hz, frame world, sensor-data QoS
 *   reads  /PEER/pose           for every other robot of --team
 * The leader drives --route once; every other robot follows the leader, its place in --team
 * times 1.5 m behind, while it hears the leader; when the leader's last pose is more than 1 s of
 * simulated time older than the robot's own (the leader out of range), it stops and waits.
 * Standard output says what happens; with --log DIR, DIR/ROBOT.csv holds every pose heard: the
 * peer, its pose's stamp, the robot's own time when it heard it (both simulated time), x, y.
 *
 *   pose_team --team a,b,c [--robot R] [--leader a] [--route X,Y:X,Y...] [--face-domain 0]
 *             [--team-domain 1] [--log DIR]
 * ROBOT defaults to $SANET_ROBOT (sanet launch --exec sets it), the leader to the team's first.
 * Ends on SIGTERM or SIGINT (sanet launch stops it when the run ends), stopping its robot. */
#include <dds/dds.h>
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "ros2_example.h"
#include "ros2_types.h"

#define PROGRAM "pose_team"
#define MAX_TEAM 16
#define MAX_ROUTE 32
#define SPACING 1.5      /* m between followers along the line to the leader */
#define STALE 1.0        /* s of simulated time after which the leader is lost */
#define LEADER_SPEED 0.8 /* m/s */
#define FOLLOW_SPEED 0.3 /* m/s: slower than the leader, which can drive out of range */

typedef struct {
  const char *robot, *leader, *log_dir;
  char *team[MAX_TEAM];
  int team_size;
  double route[MAX_ROUTE][2];
  int route_size;
  int face_domain, team_domain;
} Options;

typedef struct {
  double x, y, theta, t; /* t: simulated time of the pose (its stamp) */
  int known;
} Pose2;

typedef struct {
  dds_entity_t truth, cmd_vel, pose_out;
  dds_entity_t pose_in[MAX_TEAM]; /* 0 for the robot itself */
  Pose2 heard[MAX_TEAM];
  long count[MAX_TEAM];
  FILE *log;
} Robot;

static void usage(FILE *to, int status) {
  fprintf(to,
          "usage: pose_team --team a,b,c [--robot R] [--leader a] [--route X,Y:X,Y...] [--face-domain 0] "
          "[--team-domain 1] [--log DIR]\n"
          "One robot of a ROS 2 team over sanet's simulated radio (docs/ros2.md, \"A worked example\"): it\n"
          "publishes /R/pose in the team's domain and reads /R/ground_truth, writes /R/cmd_vel in the face's.\n"
          "R defaults to $SANET_ROBOT (sanet launch --exec sets it), the leader to the team's first.\n");
  exit(status);
}

static int parse_route(Options *o, char *text) {
  for (char *point = strtok(text, ":"); point; point = strtok(NULL, ":")) {
    if (o->route_size == MAX_ROUTE ||
        sscanf(point, "%lf,%lf", &o->route[o->route_size][0], &o->route[o->route_size][1]) != 2)
      return 0;
    ++o->route_size;
  }
  return 1;
}

static Options parse(int argc, char **argv) {
  Options o = {getenv("SANET_ROBOT"), NULL, NULL, {NULL}, 0, {{0}}, 0, 0, 1};
  static const struct option options[] = {
      {"robot", 1, NULL, 'r'}, {"team", 1, NULL, 't'},        {"leader", 1, NULL, 'l'},
      {"route", 1, NULL, 'p'}, {"face-domain", 1, NULL, 'f'}, {"team-domain", 1, NULL, 'd'},
      {"log", 1, NULL, 'o'},   {"help", 0, NULL, 'h'},        {NULL, 0, NULL, 0}};
  for (int c; (c = getopt_long(argc, argv, "", options, NULL)) != -1;) {
    switch (c) {
      case 'r':
        o.robot = optarg;
        break;
      case 'l':
        o.leader = optarg;
        break;
      case 'o':
        o.log_dir = optarg;
        break;
      case 'f':
        o.face_domain = atoi(optarg);
        break;
      case 'd':
        o.team_domain = atoi(optarg);
        break;
      case 't':
        for (char *name = strtok(strdup(optarg), ","); name && o.team_size < MAX_TEAM; name = strtok(NULL, ","))
          o.team[o.team_size++] = name;
        break;
      case 'p':
        if (parse_route(&o, strdup(optarg))) break; /* strtok cuts a copy: ps shows argv whole */
        fprintf(stderr, "pose_team: --route: give up to %d points as X,Y:X,Y...\n", MAX_ROUTE);
        exit(2);
      case 'h':
        usage(stdout, 0);
        break;
      default:
        usage(stderr, 2);
    }
  }
  if (!o.robot || !o.team_size) usage(stderr, 2);
  if (!o.leader) o.leader = o.team[0];
  return o;
}

static int index_in_team(const Options *o, const char *name) {
  for (int i = 0; i < o->team_size; ++i)
    if (strcmp(o->team[i], name) == 0) return i;
  return -1;
}

static void open_endpoints(Robot *r, const Options *o) {
  const dds_entity_t face = join(PROGRAM, o->face_domain), team = join(PROGRAM, o->team_domain);
  r->truth = endpoint(PROGRAM, face, &nav_msgs_msg_dds__Odometry__desc, o->robot, "ground_truth", 0, 0, 5);
  r->cmd_vel = endpoint(PROGRAM, face, &geometry_msgs_msg_dds__Twist__desc, o->robot, "cmd_vel", 1, 1, 10);
  r->pose_out = endpoint(PROGRAM, team, &geometry_msgs_msg_dds__PoseStamped__desc, o->robot, "pose", 1, 0, 5);
  for (int i = 0; i < o->team_size; ++i)
    if (strcmp(o->team[i], o->robot) != 0)
      r->pose_in[i] = endpoint(PROGRAM, team, &geometry_msgs_msg_dds__PoseStamped__desc, o->team[i], "pose", 0, 0, 5);
}

static Pose2 pose_of(const geometry_msgs_msg_dds__Pose_ *p, builtin_interfaces_msg_dds__Time_ stamp) {
  const geometry_msgs_msg_dds__Quaternion_ q = p->orientation;
  const Pose2 pose = {p->position.x, p->position.y, atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z)),
                      seconds(stamp), 1};
  return pose;
}

/* The latest ground truth, if any came. */
static void read_own_pose(Robot *r, Pose2 *me) {
  void *samples[8] = {NULL};
  dds_sample_info_t info[8];
  int n;
  while ((n = dds_take(r->truth, samples, info, 8, 8)) > 0) {
    for (int k = 0; k < n; ++k)
      if (info[k].valid_data) {
        const nav_msgs_msg_dds__Odometry_ *odom = samples[k];
        *me = pose_of(&odom->pose.pose, odom->header.stamp);
      }
    dds_return_loan(r->truth, samples, n);
  }
}

static void hear_peers(Robot *r, const Options *o, const Pose2 *me) {
  for (int i = 0; i < o->team_size; ++i) {
    if (!r->pose_in[i]) continue;
    void *samples[8] = {NULL};
    dds_sample_info_t info[8];
    int n;
    while ((n = dds_take(r->pose_in[i], samples, info, 8, 8)) > 0) {
      for (int k = 0; k < n; ++k) {
        if (!info[k].valid_data) continue;
        const geometry_msgs_msg_dds__PoseStamped_ *p = samples[k];
        r->heard[i] = pose_of(&p->pose, p->header.stamp);
        ++r->count[i];
        if (r->log)
          fprintf(r->log, "%s,%.3f,%.3f,%.3f,%.3f\n", o->team[i], r->heard[i].t, me->t, r->heard[i].x, r->heard[i].y);
      }
      dds_return_loan(r->pose_in[i], samples, n);
    }
  }
  if (r->log) fflush(r->log);
}

static void publish_pose(Robot *r, const Pose2 *me) {
  geometry_msgs_msg_dds__PoseStamped_ p;
  memset(&p, 0, sizeof p);
  p.header.stamp.sec = (int32_t)floor(me->t);
  p.header.stamp.nanosec = (uint32_t)((me->t - floor(me->t)) * 1e9);
  p.header.frame_id = "world";
  p.pose.position.x = me->x;
  p.pose.position.y = me->y;
  p.pose.orientation.z = sin(me->theta / 2);
  p.pose.orientation.w = cos(me->theta / 2);
  dds_write(r->pose_out, &p);
}

static void drive(Robot *r, double forward, double turn) {
  geometry_msgs_msg_dds__Twist_ twist;
  memset(&twist, 0, sizeof twist);
  twist.linear.x = forward;
  twist.angular.z = turn;
  dds_write(r->cmd_vel, &twist);
}

/* Towards (x, y) at up to `speed`: turn first, then go. */
static void go_to(Robot *r, const Pose2 *me, double x, double y, double speed) {
  const double error = remainder(atan2(y - me->y, x - me->x) - me->theta, 2 * M_PI);
  const double turn = fmax(-1.5, fmin(1.5, 2 * error));
  drive(r, fabs(error) < M_PI / 4 ? speed * cos(error) : 0, turn);
}

static void lead(Robot *r, const Options *o, const Pose2 *me, int *next) {
  if (*next == o->route_size) {
    drive(r, 0, 0);
    return;
  }
  const double *to = o->route[*next], distance = hypot(to[0] - me->x, to[1] - me->y);
  if (distance < 0.3) {
    printf("%s %.1f s: reached route point %d (%.1f, %.1f)\n", o->robot, me->t, *next + 1, to[0], to[1]);
    ++*next;
    drive(r, 0, 0);
    return;
  }
  go_to(r, me, to[0], to[1], fmin(LEADER_SPEED, distance));
}

static void follow(Robot *r, const Options *o, const Pose2 *me, int *following) {
  const int l = index_in_team(o, o->leader);
  const Pose2 *leader = &r->heard[l];
  const int hears = leader->known && me->t - leader->t <= STALE;
  const double distance = leader->known ? hypot(leader->x - me->x, leader->y - me->y) : 0;
  if (hears != *following)
    printf(
        hears ? "%s %.1f s: following %s, %.1f m away\n" : "%s %.1f s: lost %s (nothing heard for %.1f s); waiting\n",
        o->robot, me->t, o->leader, hears ? distance : STALE);
  *following = hears;
  const double place = SPACING * index_in_team(o, o->robot);
  if (hears && distance > place)
    go_to(r, me, leader->x, leader->y, fmin(FOLLOW_SPEED, distance - place));
  else
    drive(r, 0, 0);
}

static void say_what_was_heard(const Robot *r, const Options *o) {
  printf("%s: heard", o->robot);
  for (int i = 0; i < o->team_size; ++i)
    if (r->pose_in[i]) printf(" %s %ld poses", o->team[i], r->count[i]);
  printf("\n");
}

int main(int argc, char **argv) {
  const Options o = parse(argc, argv);
  if (index_in_team(&o, o.robot) < 0 || index_in_team(&o, o.leader) < 0) {
    fprintf(stderr, "pose_team: the robot (%s) and the leader (%s) must be in --team\n", o.robot, o.leader);
    return 2;
  }
  setvbuf(stdout, NULL, _IOLBF, 0);
  stop_on_signals();
  Robot r;
  memset(&r, 0, sizeof r);
  open_endpoints(&r, &o);
  r.log = open_log(o.log_dir, o.robot, "", "peer,stamp,heard_at,x,y");
  Pose2 me = {0, 0, 0, 0, 0};
  double published = -1;
  int next = 0, following = 0;
  while (!stopping) {
    read_own_pose(&r, &me);
    hear_peers(&r, &o, &me);
    if (me.known && me.t - published >= 0.2) publish_pose(&r, &me), published = me.t;
    if (me.known && strcmp(o.robot, o.leader) == 0)
      lead(&r, &o, &me, &next);
    else if (me.known)
      follow(&r, &o, &me, &following);
    dds_sleepfor(DDS_MSECS(50));
  }
  drive(&r, 0, 0);
  say_what_was_heard(&r, &o);
  if (r.log) fclose(r.log);
  /* No dds_delete: when the run ends, radio0 goes with the server, and Cyclone's shutdown would
   * wait for a packet on it that can no longer come. The process's end frees everything. */
  fflush(stdout);
  _exit(0);
}
