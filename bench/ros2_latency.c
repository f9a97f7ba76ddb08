/* The ROS 2 side of bench/ros2_face.py: drives N robots of sanet's ROS 2 face over DDS (types
 * from tests/ros2/ros2_types.idl, Cyclone's own encoder) and measures, on this machine's
 * monotonic clock (the server's ClockOrigin is on it too):
 *   command: from publishing a cmd_vel that starts a still robot to receiving the first
 *            /R/ground_truth read after it whose position has moved more than 2 mm;
 *   sensor:  from the simulated time a /R/ground_truth was read (ClockOrigin + its stamp) to
 *            its arrival here.
 * Each robot goes and stops by turns every 0.5 s, the robots staggered. Prints every latency in ms as
 * `command X` and `sensor X` lines.
 *
 *   ros2_latency DOMAIN CLOCK_ORIGIN SECONDS COUNT PREFIX */
#include <dds/dds.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "ros2_types.h"

#define MOST 64

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + t.tv_nsec * 1e-9;
}

struct robot {
  dds_entity_t truth, cmd;
  int going;            /* the last command: 1 go, 0 stop */
  double sent;          /* when a go was sent; 0 once its effect was seen */
  double x, y;          /* where the robot was when it was sent */
  double last_x, last_y;
  double next;          /* when to send the next command */
};

int main(int argc, char **argv) {
  if (argc < 6) {
    fprintf(stderr, "usage: ros2_latency DOMAIN CLOCK_ORIGIN SECONDS COUNT PREFIX\n");
    return 2;
  }
  const double origin = atof(argv[2]), seconds = atof(argv[3]);
  const int count = atoi(argv[4]) < MOST ? atoi(argv[4]) : MOST;
  dds_entity_t participant = dds_create_participant((dds_domainid_t)atoi(argv[1]), NULL, NULL);
  dds_qos_t *best = dds_create_qos(), *reliable = dds_create_qos();
  dds_qset_reliability(best, DDS_RELIABILITY_BEST_EFFORT, 0);
  dds_qset_history(best, DDS_HISTORY_KEEP_LAST, 5);
  dds_qset_reliability(reliable, DDS_RELIABILITY_RELIABLE, DDS_MSECS(100));
  struct robot robots[MOST];
  char name[128];
  const double start = now();
  for (int i = 0; i < count; ++i) {
    snprintf(name, sizeof name, "rt/%s%d/ground_truth", argv[5], i);
    robots[i].truth = dds_create_reader(
        participant, dds_create_topic(participant, &nav_msgs_msg_dds__Odometry__desc, name, NULL, NULL), best, NULL);
    snprintf(name, sizeof name, "rt/%s%d/cmd_vel", argv[5], i);
    robots[i].cmd = dds_create_writer(
        participant, dds_create_topic(participant, &geometry_msgs_msg_dds__Twist__desc, name, NULL, NULL), reliable,
        NULL);
    robots[i].going = 0;
    robots[i].sent = 0;
    robots[i].last_x = robots[i].last_y = NAN;
    robots[i].next = start + 2.0 + 0.5 * i / count; /* discovery first, then staggered */
  }
  while (now() - start < seconds) {
    for (int i = 0; i < count; ++i) {
      struct robot *r = &robots[i];
      void *s[8] = {NULL};
      dds_sample_info_t info[8];
      int n;
      while ((n = dds_take(r->truth, s, info, 8, 8)) > 0) {
        const double arrived = now();
        for (int k = 0; k < n; ++k) {
          if (!info[k].valid_data) continue;
          const nav_msgs_msg_dds__Odometry_ *o = s[k];
          const double read = origin + o->header.stamp.sec + o->header.stamp.nanosec * 1e-9;
          printf("sensor %.3f\n", 1000 * (arrived - read));
          r->last_x = o->pose.pose.position.x;
          r->last_y = o->pose.pose.position.y;
          if (r->going && r->sent > 0 && read > r->sent && hypot(r->last_x - r->x, r->last_y - r->y) > 0.002) {
            printf("command %.3f\n", 1000 * (arrived - r->sent));
            r->sent = 0;
          }
        }
        dds_return_loan(r->truth, s, n);
      }
      if (now() >= r->next && !isnan(r->last_x)) {
        geometry_msgs_msg_dds__Twist_ t;
        memset(&t, 0, sizeof t);
        r->going = !r->going;
        t.linear.x = r->going ? 0.3 : 0;
        r->x = r->last_x;
        r->y = r->last_y;
        r->sent = now();
        dds_write(r->cmd, &t);
        r->next += 0.5;
      }
    }
    dds_sleepfor(DDS_MSECS(1));
  }
  dds_delete(participant);
  return 0;
}
