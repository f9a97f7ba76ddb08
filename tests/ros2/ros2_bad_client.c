/* A DDS publisher that gets a robot's cmd_vel type wrong: ROS 2's Twist name over a struct that
 * is not a Twist (bad_twist.idl). sanet's face must count its samples, not crash.
 *
 *   ros2_bad_client DOMAIN ROBOT SECONDS */
#include <dds/dds.h>
#include <stdio.h>
#include <stdlib.h>

#include "bad_twist.h"

int main(int argc, char **argv) {
  if (argc < 4) {
    fprintf(stderr, "usage: ros2_bad_client DOMAIN ROBOT SECONDS\n");
    return 2;
  }
  dds_entity_t participant = dds_create_participant((dds_domainid_t)atoi(argv[1]), NULL, NULL);
  char name[256];
  snprintf(name, sizeof name, "rt/%s/cmd_vel", argv[2]);
  dds_entity_t topic = dds_create_topic(participant, &geometry_msgs_msg_dds__Twist__desc, name, NULL, NULL);
  dds_qos_t *q = dds_create_qos();
  dds_qset_reliability(q, DDS_RELIABILITY_RELIABLE, DDS_MSECS(100));
  dds_entity_t writer = dds_create_writer(participant, topic, q, NULL);
  dds_delete_qos(q);
  long sent = 0;
  for (long i = 0; i < (long)(atof(argv[3]) * 50); ++i) {
    geometry_msgs_msg_dds__Twist_ bad = {42};
    if (dds_write(writer, &bad) == DDS_RETCODE_OK) ++sent;
    dds_sleepfor(DDS_MSECS(20));
  }
  printf("sent %ld\n", sent);
  dds_delete(participant);
  return 0;
}
