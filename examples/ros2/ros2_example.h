/* What the ROS 2 examples (pose_team, image_relay) share: ROS 2's topics on plain Cyclone DDS,
 * and the way they stop. Each example is one C file beside this header. */
#ifndef SANET_EXAMPLES_ROS2_EXAMPLE_H
#define SANET_EXAMPLES_ROS2_EXAMPLE_H

#include <dds/dds.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>

#include "ros2_types.h"

/* Set by SIGTERM or SIGINT (sanet launch stops --exec programs with SIGTERM when the run ends). */
static volatile sig_atomic_t stopping = 0;
static void on_signal(int signal_number) {
  (void)signal_number;
  stopping = 1;
}
static void stop_on_signals(void) {
  signal(SIGTERM, on_signal);
  signal(SIGINT, on_signal);
}

static double seconds(builtin_interfaces_msg_dds__Time_ t) { return t.sec + t.nanosec * 1e-9; }

static dds_entity_t join(const char *program, int domain) {
  const dds_entity_t participant = dds_create_participant((dds_domainid_t)domain, NULL, NULL);
  if (participant < 0) {
    fprintf(stderr, "%s: cannot join DDS domain %d: %s (does CYCLONEDDS_URI name interfaces here?)\n", program, domain,
            dds_strretcode(participant));
    exit(1);
  }
  return participant;
}

/* A reader or writer of ROS 2 topic /ROBOT/TOPIC (or /TOPIC where `robot` is NULL): ROS 2's default
 * profile (reliable, keep last 10) where `reliable`, else its sensor-data one (best effort, keep
 * last `depth`). */
static dds_entity_t endpoint(const char *program, dds_entity_t participant, const dds_topic_descriptor_t *type,
                             const char *robot, const char *topic, int writer, int reliable, int depth) {
  char name[256];
  if (robot)
    snprintf(name, sizeof name, "rt/%s/%s", robot, topic); /* ROS 2 topic /robot/topic */
  else
    snprintf(name, sizeof name, "rt/%s", topic);
  const dds_entity_t t = dds_create_topic(participant, type, name, NULL, NULL);
  dds_qos_t *q = dds_create_qos();
  dds_qset_reliability(q, reliable ? DDS_RELIABILITY_RELIABLE : DDS_RELIABILITY_BEST_EFFORT, DDS_MSECS(100));
  dds_qset_history(q, DDS_HISTORY_KEEP_LAST, reliable ? 10 : depth);
  const dds_entity_t e =
      writer ? dds_create_writer(participant, t, q, NULL) : dds_create_reader(participant, t, q, NULL);
  dds_delete_qos(q);
  if (t < 0 || e < 0) {
    fprintf(stderr, "%s: cannot use %s: %s\n", program, name, dds_strretcode(t < 0 ? t : e));
    exit(1);
  }
  return e;
}

/* DIR/ROBOTSUFFIX.csv with its header line, for writing (`dir` NULL: no log, NULL). */
static FILE *open_log(const char *dir, const char *robot, const char *suffix, const char *header) {
  if (!dir) return NULL;
  mkdir(dir, 0777); /* each robot's program may be first */
  char path[1024];
  snprintf(path, sizeof path, "%s/%s%s.csv", dir, robot, suffix);
  FILE *log = fopen(path, "w");
  if (!log) {
    perror(path);
    exit(1);
  }
  fprintf(log, "%s\n", header);
  return log;
}

#endif
