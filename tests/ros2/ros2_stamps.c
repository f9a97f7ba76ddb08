/* The stamps of a ROS 2 face's sensor topics, as an independent client sees them (C on Cyclone
 * DDS, types from ros2_types.idl): for SECONDS it reads each TOPIC (sensor-data QoS) and prints a
 * line `TOPIC STAMP` per message, STAMP its header's stamp in seconds.
 *
 *   ros2_stamps DOMAIN SECONDS /R/imu=imu /R/camera/image_raw=image ...   (types: imu, image) */
#include <dds/dds.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ros2_types.h"

#define MOST_TOPICS 8

static dds_entity_t reader(dds_entity_t participant, const dds_topic_descriptor_t *type, const char *ros_topic) {
  char name[256];
  snprintf(name, sizeof name, "rt%s", ros_topic);
  dds_qos_t *q = dds_create_qos();
  dds_qset_reliability(q, DDS_RELIABILITY_BEST_EFFORT, 0);
  dds_qset_history(q, DDS_HISTORY_KEEP_LAST, 100);
  const dds_entity_t topic = dds_create_topic(participant, type, name, NULL, NULL);
  const dds_entity_t r = dds_create_reader(participant, topic, q, NULL);
  dds_delete_qos(q);
  if (topic < 0 || r < 0) {
    fprintf(stderr, "ros2_stamps: cannot read %s\n", ros_topic);
    exit(2);
  }
  return r;
}

/* Both types begin with a std_msgs/Header. */
static const std_msgs_msg_dds__Header_ *header_of(const void *sample, int is_image) {
  return is_image ? &((const sensor_msgs_msg_dds__Image_ *)sample)->header
                  : &((const sensor_msgs_msg_dds__Imu_ *)sample)->header;
}

int main(int argc, char **argv) {
  if (argc < 4 || argc - 3 > MOST_TOPICS) {
    fprintf(stderr, "usage: ros2_stamps DOMAIN SECONDS TOPIC=imu|image ... (up to %d)\n", MOST_TOPICS);
    return 2;
  }
  const dds_entity_t participant = dds_create_participant((dds_domainid_t)atoi(argv[1]), NULL, NULL);
  const long steps = (long)(atof(argv[2]) * 50);
  const int count = argc - 3;
  dds_entity_t readers[MOST_TOPICS];
  int is_image[MOST_TOPICS];
  char *topics[MOST_TOPICS];
  for (int i = 0; i < count; ++i) {
    topics[i] = strdup(argv[3 + i]);
    char *type = strchr(topics[i], '=');
    if (!type) return 2;
    *type++ = '\0';
    is_image[i] = strcmp(type, "image") == 0;
    readers[i] = reader(participant, is_image[i] ? &sensor_msgs_msg_dds__Image__desc : &sensor_msgs_msg_dds__Imu__desc,
                        topics[i]);
  }
  for (long step = 0; step < steps; ++step) {
    dds_sleepfor(DDS_MSECS(20));
    for (int i = 0; i < count; ++i) {
      void *samples[32] = {NULL};
      dds_sample_info_t info[32];
      int n;
      while ((n = dds_take(readers[i], samples, info, 32, 32)) > 0) {
        for (int k = 0; k < n; ++k) {
          if (!info[k].valid_data) continue;
          const std_msgs_msg_dds__Header_ *h = header_of(samples[k], is_image[i]);
          printf("%s %.6f\n", topics[i], h->stamp.sec + h->stamp.nanosec * 1e-9);
        }
        dds_return_loan(readers[i], samples, n);
      }
    }
  }
  dds_delete(participant);
  for (int i = 0; i < count; ++i) free(topics[i]);
  return 0;
}
