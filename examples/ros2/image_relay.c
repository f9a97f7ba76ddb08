/* Camera pictures of a ROS 2 robot, relayed to its team over sanet's simulated radio: the example
 * of docs/camera.md ("ROS 2 pictures over the radio"). Plain C on Cyclone DDS, speaking ROS 2's
 * topics, types and QoS, so that it runs where ROS 2 is not installed; a ROS 2 user would write
 * the same with rclcpp and image_transport's compressed publisher.
 *
 * On a robot named in --senders:
 *   face's domain (--face-domain, 0; Cyclone on sim0, the link to the simulator):
 *     reads  /ROBOT/camera/image_raw             sensor_msgs/msg/Image (rgb8)
 *     writes /ROBOT/cmd_vel                      with --drive V: V m/s straight ahead, at most 10 times a second
 *   team's domain (--team-domain, 1; Cyclone on radio0, the simulated radio):
 *     writes /ROBOT/camera/image_raw/compressed  sensor_msgs/msg/CompressedImage, PNG, sensor-data QoS:
 *                                                every picture the face publishes, or at most --rate a
 *                                                second of simulated time
 * On every other robot:
 *   face's domain: reads /clock (rosgraph_msgs/msg/Clock), the simulated time
 *   team's domain: reads /SENDER/camera/image_raw/compressed of every sender, and decodes each picture
 * With --log DIR: DIR/ROBOT-sent.csv, each picture relayed (its stamp, PNG bytes, CRC-32 of its
 * pixels); DIR/ROBOT.csv, each picture heard (the sender, its stamp, the simulated time it was
 * heard at, PNG bytes, width, height, CRC-32 of the decoded pixels: equal to the sender's when
 * the picture arrived whole).
 *
 *   image_relay --senders a[,b...] [--robot R] [--rate HZ] [--drive V] [--face-domain 0] [--team-domain 1]
 *               [--log DIR]
 * ROBOT defaults to $SANET_ROBOT (sanet launch --exec sets it). Ends on SIGTERM or SIGINT. */
#include <dds/dds.h>
#include <getopt.h>
#include <math.h>
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include <zlib.h>

#include "ros2_example.h"
#include "ros2_types.h"

#define PROGRAM "image_relay"
#define MAX_SENDERS 16
#define QUIET 3.0 /* s of simulated time without a picture after which a sender is said to be unheard */

typedef struct {
  const char *robot, *log_dir;
  char *senders[MAX_SENDERS];
  int sender_count;
  double rate, drive;
  int face_domain, team_domain;
} Options;

typedef struct {
  dds_entity_t waitset, image_in, cmd_vel, image_out; /* a sender's */
  double relayed_at, driven_at;                       /* simulated stamp; monotonic s */
  long relayed, said_unfit;
} Sender;

typedef struct {
  dds_entity_t waitset, clock_in, images_in[MAX_SENDERS];
  double clock, clock_taken_at; /* the latest /clock, and the monotonic s it came at (0: none yet) */
  double last_heard[MAX_SENDERS];
  long heard[MAX_SENDERS];
} Receiver;

static void usage(FILE *to, int status) {
  fprintf(to,
          "usage: image_relay --senders a[,b...] [--robot R] [--rate HZ] [--drive V] [--face-domain 0] "
          "[--team-domain 1] [--log DIR]\n"
          "Relays the camera pictures of the --senders from the ROS 2 face's domain to the team's, as PNG\n"
          "(/R/camera/image_raw -> /R/camera/image_raw/compressed), and on every other robot receives them\n"
          "(docs/camera.md, \"ROS 2 pictures over the radio\"). R defaults to $SANET_ROBOT.\n"
          "  --rate HZ     a picture at least 1/HZ s of simulated time after the last relayed (default: every\n"
          "                picture; a 5 Hz camera with --rate 2 gives one every 0.6 s)\n"
          "  --drive V     a sender also drives straight ahead at V m/s (default: it does not move)\n"
          "  --log DIR     DIR/R-sent.csv: the pictures relayed; DIR/R.csv: the pictures heard\n");
  exit(status);
}

static void refuse(const char *format, const char *detail) {
  fprintf(stderr, "image_relay: ");
  fprintf(stderr, format, detail);
  fprintf(stderr, " (--help says more)\n");
  exit(2);
}

static double number(const char *option, const char *text) {
  char *end;
  const double value = strtod(text, &end);
  if (*text == '\0' || *end != '\0' || !isfinite(value)) {
    fprintf(stderr, "image_relay: %s takes a number, not '%s'\n", option, text);
    exit(2);
  }
  return value;
}

static Options parse(int argc, char **argv) {
  Options o = {getenv("SANET_ROBOT"), NULL, {NULL}, 0, 0.0, 0.0, 0, 1};
  static const struct option options[] = {
      {"robot", 1, NULL, 'r'}, {"senders", 1, NULL, 's'},     {"rate", 1, NULL, 'q'},
      {"drive", 1, NULL, 'v'}, {"face-domain", 1, NULL, 'f'}, {"team-domain", 1, NULL, 'd'},
      {"log", 1, NULL, 'o'},   {"help", 0, NULL, 'h'},        {NULL, 0, NULL, 0}};
  for (int c; (c = getopt_long(argc, argv, "", options, NULL)) != -1;) {
    if (c == 'r')
      o.robot = optarg;
    else if (c == 'o')
      o.log_dir = optarg;
    else if (c == 'q')
      o.rate = number("--rate", optarg);
    else if (c == 'v')
      o.drive = number("--drive", optarg);
    else if (c == 'f')
      o.face_domain = (int)number("--face-domain", optarg);
    else if (c == 'd')
      o.team_domain = (int)number("--team-domain", optarg);
    else if (c == 's')
      for (char *name = strtok(strdup(optarg), ","); name; name = strtok(NULL, ",")) {
        if (o.sender_count == MAX_SENDERS) {
          fprintf(stderr, "image_relay: --senders: at most %d robots\n", MAX_SENDERS);
          exit(2);
        }
        o.senders[o.sender_count++] = name;
      }
    else
      usage(c == 'h' ? stdout : stderr, c == 'h' ? 0 : 2);
  }
  if (optind < argc) refuse("unexpected argument '%s' (options only)", argv[optind]);
  if (!o.robot)
    refuse("which robot? give --robot R, or run it under sanet launch --exec, which sets $SANET_ROBOT%s", "");
  if (!o.sender_count) refuse("give the robots whose pictures are relayed: --senders a[,b...]%s", "");
  if (o.rate < 0) refuse("--rate must be 0 (every picture) or more%s", "");
  return o;
}

static double monotonic(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + t.tv_nsec * 1e-9;
}

#define UNMATCHED_AFTER 10.0 /* s of wall time before a reader that found no publisher says so */

/* Says once, `UNMATCHED_AFTER` s after `since`, that `reader` of `topic` has found no publisher,
 * and what may be wrong (`hint`): a typo in a robot's name otherwise waits silently to the end. */
static void say_if_unmatched(dds_entity_t reader, double since, int *said, const char *robot, const char *topic,
                             const char *hint) {
  dds_subscription_matched_status_t status;
  if (*said || monotonic() - since < UNMATCHED_AFTER) return;
  *said = 1;
  if (dds_get_subscription_matched_status(reader, &status) == DDS_RETCODE_OK && status.total_count == 0)
    printf("%s: no publisher of %s found in %.0f s: %s\n", robot, topic, UNMATCHED_AFTER, hint);
}

/* Wakes the loop when `reader` has data. */
static void wake_on(dds_entity_t waitset, dds_entity_t reader) {
  const dds_entity_t condition = dds_create_readcondition(reader, DDS_ANY_STATE);
  dds_waitset_attach(waitset, condition, reader);
}

static int is_sender(const Options *o, const char *name) {
  for (int i = 0; i < o->sender_count; ++i)
    if (strcmp(o->senders[i], name) == 0) return 1;
  return 0;
}

/* ---- On a sender ---- */

typedef struct {
  unsigned char *bytes;
  size_t size, capacity;
} Buffer;

static void append(void *to, void *bytes, int size) {
  Buffer *b = to;
  if (b->size + (size_t)size > b->capacity) {
    b->capacity = 2 * (b->size + (size_t)size);
    b->bytes = realloc(b->bytes, b->capacity);
    if (!b->bytes) {
      fprintf(stderr, "image_relay: out of memory\n");
      exit(1);
    }
  }
  memcpy(b->bytes + b->size, bytes, (size_t)size);
  b->size += (size_t)size;
}

/* The CRC-32 of a picture's pixels, row by row (`step` bytes apart), without any row padding:
 * what the receiver computes from the decoded PNG. */
static uLong pixels_crc(const unsigned char *pixels, size_t width, size_t height, size_t step) {
  uLong crc = crc32(0L, Z_NULL, 0);
  for (size_t row = 0; row < height; ++row) crc = crc32(crc, pixels + row * step, (uInt)(width * 3));
  return crc;
}

/* Whether an Image is an rgb8 picture whose data holds its rows: another publisher on the topic
 * may send anything. */
static int is_whole_rgb8(const sensor_msgs_msg_dds__Image_ *image) {
  const uint64_t row = (uint64_t)image->width * 3;
  return strcmp(image->encoding, "rgb8") == 0 && image->width > 0 && image->height > 0 && image->width < (1u << 16) &&
         image->height < (1u << 16) && image->step >= row &&
         (uint64_t)image->data._length >= (uint64_t)image->step * (image->height - 1) + row;
}

/* The picture as image_transport's compressed publisher sends an rgb8 image: PNG, and the format
 * its subscriber reads back to rgb8. */
static void relay(Sender *s, const Options *o, const sensor_msgs_msg_dds__Image_ *image, FILE *log) {
  Buffer png = {NULL, 0, 0};
  if (!stbi_write_png_to_func(append, &png, (int)image->width, (int)image->height, 3, image->data._buffer,
                              (int)image->step)) {
    fprintf(stderr, "%s: a picture of %u x %u did not encode as PNG; not relayed\n", o->robot, image->width,
            image->height);
    free(png.bytes);
    return;
  }
  sensor_msgs_msg_dds__CompressedImage_ out;
  memset(&out, 0, sizeof out);
  out.header = image->header;
  out.format = "rgb8; png compressed bgr8";
  out.data._buffer = png.bytes;
  out.data._length = out.data._maximum = (uint32_t)png.size;
  dds_write(s->image_out, &out);
  if (log) {
    const uLong crc = pixels_crc(image->data._buffer, image->width, image->height, image->step);
    fprintf(log, "%.3f,%zu,%08lx\n", seconds(image->header.stamp), png.size, crc);
    fflush(log);
  }
  free(png.bytes);
  if (++s->relayed == 1) printf("%s: relaying its camera's pictures to the team\n", o->robot);
}

static void relay_new_pictures(Sender *s, const Options *o, FILE *log) {
  void *samples[4] = {NULL};
  dds_sample_info_t info[4];
  int n;
  while ((n = dds_take(s->image_in, samples, info, 4, 4)) > 0) {
    for (int k = 0; k < n; ++k) {
      const sensor_msgs_msg_dds__Image_ *image = samples[k];
      if (!info[k].valid_data) continue;
      if (!is_whole_rgb8(image)) {
        if (!s->said_unfit++)
          fprintf(stderr, "%s: an Image that is not a whole rgb8 picture (%s, %u x %u, step %u, %u bytes); skipped\n",
                  o->robot, image->encoding, image->width, image->height, image->step, image->data._length);
        continue;
      }
      const double stamp = seconds(image->header.stamp);
      if (o->rate > 0 && stamp - s->relayed_at < 1 / o->rate - 1e-6) continue;
      s->relayed_at = stamp;
      relay(s, o, image, log);
    }
    dds_return_loan(s->image_in, samples, n);
  }
}

static void drive(Sender *s, double forward) {
  geometry_msgs_msg_dds__Twist_ twist;
  memset(&twist, 0, sizeof twist);
  twist.linear.x = forward;
  dds_write(s->cmd_vel, &twist);
}

static void run_sender(const Options *o) {
  const dds_entity_t face = join(PROGRAM, o->face_domain), team = join(PROGRAM, o->team_domain);
  Sender s = {dds_create_waitset(face), 0, 0, 0, -INFINITY, 0, 0, 0};
  s.image_in = endpoint(PROGRAM, face, &sensor_msgs_msg_dds__Image__desc, o->robot, "camera/image_raw", 0, 0, 1);
  s.image_out = endpoint(PROGRAM, team, &sensor_msgs_msg_dds__CompressedImage__desc, o->robot,
                         "camera/image_raw/compressed", 1, 0, 1);
  if (o->drive != 0)
    s.cmd_vel = endpoint(PROGRAM, face, &geometry_msgs_msg_dds__Twist__desc, o->robot, "cmd_vel", 1, 1, 1);
  wake_on(s.waitset, s.image_in);
  FILE *log = open_log(o->log_dir, o->robot, "-sent", "stamp,bytes,crc32");
  char topic[256];
  snprintf(topic, sizeof topic, "/%s/camera/image_raw", o->robot);
  const double started = monotonic();
  int said_unmatched = 0;
  while (!stopping) {
    dds_waitset_wait(s.waitset, NULL, 0, DDS_MSECS(100));
    relay_new_pictures(&s, o, log);
    say_if_unmatched(s.image_in, started, &said_unmatched, o->robot, topic,
                     "does this robot have a camera (sensors: {camera: ...}), and is the face in --face-domain?");
    if (s.cmd_vel && monotonic() - s.driven_at >= 0.1) drive(&s, o->drive), s.driven_at = monotonic();
  }
  if (s.cmd_vel) drive(&s, 0);
  printf("%s: relayed %ld pictures\n", o->robot, s.relayed);
  if (log) fclose(log);
}

/* ---- On a receiver ---- */

/* The simulated time now: the latest /clock and the time since it came (the run keeps real time). */
static double now(const Receiver *r) {
  return r->clock_taken_at > 0 ? r->clock + (monotonic() - r->clock_taken_at) : 0;
}

static void read_clock(Receiver *r) {
  void *samples[8] = {NULL};
  dds_sample_info_t info[8];
  int n;
  while ((n = dds_take(r->clock_in, samples, info, 8, 8)) > 0) {
    for (int k = 0; k < n; ++k)
      if (info[k].valid_data) {
        r->clock = seconds(((const rosgraph_msgs_msg_dds__Clock_ *)samples[k])->clock);
        r->clock_taken_at = monotonic();
      }
    dds_return_loan(r->clock_in, samples, n);
  }
}

static void heard(Receiver *r, const Options *o, int i, const sensor_msgs_msg_dds__CompressedImage_ *picture,
                  FILE *log) {
  const double at = now(r);
  if (r->heard[i] == 0 || at - r->last_heard[i] > QUIET)
    printf("%s %.1f s: hearing %s's pictures\n", o->robot, at, o->senders[i]);
  r->last_heard[i] = at;
  ++r->heard[i];
  int width = 0, height = 0, channels = 0;
  unsigned char *pixels =
      stbi_load_from_memory(picture->data._buffer, (int)picture->data._length, &width, &height, &channels, 3);
  const uLong crc = pixels ? pixels_crc(pixels, (size_t)width, (size_t)height, (size_t)width * 3) : 0;
  stbi_image_free(pixels);
  if (!log) return;
  fprintf(log, "%s,%.3f,", o->senders[i], seconds(picture->header.stamp));
  if (r->clock_taken_at > 0) fprintf(log, "%.3f", at); /* before the first /clock, no time to give */
  fprintf(log, ",%u,%d,%d,%08lx\n", picture->data._length, width, height, crc);
}

static void hear_pictures(Receiver *r, const Options *o, FILE *log) {
  for (int i = 0; i < o->sender_count; ++i) {
    void *samples[4] = {NULL};
    dds_sample_info_t info[4];
    int n;
    while ((n = dds_take(r->images_in[i], samples, info, 4, 4)) > 0) {
      for (int k = 0; k < n; ++k)
        if (info[k].valid_data) heard(r, o, i, samples[k], log);
      dds_return_loan(r->images_in[i], samples, n);
    }
    if (r->heard[i] && r->last_heard[i] > 0 && now(r) - r->last_heard[i] > QUIET) {
      printf("%s %.1f s: nothing of %s's for %.0f s\n", o->robot, now(r), o->senders[i], QUIET);
      r->last_heard[i] = -1; /* said once until heard again */
    }
  }
  if (log) fflush(log);
}

static void run_receiver(const Options *o) {
  const dds_entity_t face = join(PROGRAM, o->face_domain), team = join(PROGRAM, o->team_domain);
  Receiver r;
  memset(&r, 0, sizeof r);
  r.waitset = dds_create_waitset(team);
  r.clock_in = endpoint(PROGRAM, face, &rosgraph_msgs_msg_dds__Clock__desc, NULL, "clock", 0, 0, 1);
  for (int i = 0; i < o->sender_count; ++i) {
    r.images_in[i] = endpoint(PROGRAM, team, &sensor_msgs_msg_dds__CompressedImage__desc, o->senders[i],
                              "camera/image_raw/compressed", 0, 0, 1);
    wake_on(r.waitset, r.images_in[i]);
  }
  FILE *log = open_log(o->log_dir, o->robot, "", "peer,stamp,heard_at,bytes,width,height,crc32");
  const double started = monotonic();
  int said_unmatched[MAX_SENDERS] = {0};
  while (!stopping) {
    dds_waitset_wait(r.waitset, NULL, 0, DDS_MSECS(20));
    read_clock(&r);
    hear_pictures(&r, o, log);
    for (int i = 0; i < o->sender_count; ++i) {
      char topic[256];
      snprintf(topic, sizeof topic, "/%s/camera/image_raw/compressed", o->senders[i]);
      say_if_unmatched(r.images_in[i], started, &said_unmatched[i], o->robot, topic,
                       "is it a robot's name (a robot, not a mote), relaying, and in radio range?");
    }
  }
  for (int i = 0; i < o->sender_count; ++i)
    printf("%s: heard %ld pictures of %s\n", o->robot, r.heard[i], o->senders[i]);
  if (log) fclose(log);
}

int main(int argc, char **argv) {
  const Options o = parse(argc, argv);
  setvbuf(stdout, NULL, _IOLBF, 0);
  stop_on_signals();
  if (is_sender(&o, o.robot))
    run_sender(&o);
  else
    run_receiver(&o);
  /* No dds_delete: when the run ends, radio0 goes with the server, and Cyclone's shutdown would
   * wait for a packet on it that can no longer come. The process's end frees everything. */
  fflush(stdout);
  _exit(0);
}
