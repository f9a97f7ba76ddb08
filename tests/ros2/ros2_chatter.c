/* A ROS 2-style chatter over plain DDS (Cyclone, types from ros2_types.idl): `pub` publishes
 * std_msgs/Header-typed samples on ROS topic /chatter (DDS rt/chatter) ten times a second, each
 * with its sequence number as frame_id; `sub` prints every sequence number it hears. With the
 * default QoS of ROS 2 (reliable, volatile, keep last 10) and Cyclone's default discovery
 * (multicast) unless CYCLONEDDS_URI says otherwise.
 *
 *   ros2_chatter pub|sub DOMAIN SECONDS */
#include <dds/dds.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ros2_types.h"

int main(int argc, char **argv) {
  if (argc < 4 || (strcmp(argv[1], "pub") && strcmp(argv[1], "sub"))) {
    fprintf(stderr, "usage: ros2_chatter pub|sub DOMAIN SECONDS\n");
    return 2;
  }
  const int publishing = strcmp(argv[1], "pub") == 0;
  const long ticks = (long)(atof(argv[3]) * 10);
  dds_entity_t participant = dds_create_participant((dds_domainid_t)atoi(argv[2]), NULL, NULL);
  if (participant < 0) {
    fprintf(stderr, "ros2_chatter: %s\n", dds_strretcode(participant));
    return 1;
  }
  dds_entity_t topic = dds_create_topic(participant, &std_msgs_msg_dds__Header__desc, "rt/chatter", NULL, NULL);
  dds_qos_t *q = dds_create_qos();
  dds_qset_reliability(q, DDS_RELIABILITY_RELIABLE, DDS_MSECS(100));
  dds_qset_history(q, DDS_HISTORY_KEEP_LAST, 10);
  dds_entity_t endpoint =
      publishing ? dds_create_writer(participant, topic, q, NULL) : dds_create_reader(participant, topic, q, NULL);
  dds_delete_qos(q);
  char text[32];
  for (long i = 0; i < ticks; ++i) {
    if (publishing) {
      std_msgs_msg_dds__Header_ h;
      memset(&h, 0, sizeof h);
      snprintf(text, sizeof text, "%ld", i);
      h.frame_id = text;
      dds_write(endpoint, &h);
    } else {
      void *s[16] = {NULL};
      dds_sample_info_t info[16];
      int n;
      while ((n = dds_take(endpoint, s, info, 16, 16)) > 0) {
        for (int k = 0; k < n; ++k)
          if (info[k].valid_data) printf("%s\n", ((std_msgs_msg_dds__Header_ *)s[k])->frame_id);
        dds_return_loan(endpoint, s, n);
      }
      fflush(stdout);
    }
    dds_sleepfor(DDS_MSECS(100));
  }
  dds_delete(participant);
  return 0;
}
