/* CDR encode/decode time per message of Cyclone DDS's C serializer on
 * idlc-generated types (the C side of bench/bench-typed.sh): the same
 * messages as bin/bench_typed_cdr. Encode = sample -> serdata -> bytes in a
 * kept buffer; decode = bytes -> serdata -> a kept sample (what a C writer
 * and reader do per message).
 *   typed_cdr_c SECONDS  prints "case,op,c,bytes,iterations,ns_per_msg" */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "dds/dds.h"
#include "dds/ddsi/ddsi_serdata.h"
#include "dds/ddsi/ddsi_sertype.h"
#include "typed_cdr.h"

static double now (void)
{
  struct timespec t;
  clock_gettime (CLOCK_MONOTONIC, &t);
  return (double) t.tv_sec + (double) t.tv_nsec * 1e-9;
}

static volatile unsigned char sink;

static void measure (dds_entity_t participant, const char *name, const dds_topic_descriptor_t *desc,
                     const void *sample, void *kept, double budget)
{
  char topic_name[64];
  snprintf (topic_name, sizeof topic_name, "bench_%s", name);
  dds_entity_t topic = dds_create_topic (participant, desc, topic_name, NULL, NULL);
  const struct ddsi_sertype *st;
  if (topic < 0 || dds_get_entity_sertype (topic, &st) < 0) { fprintf (stderr, "topic\n"); exit (1); }
  struct ddsi_serdata *sd = ddsi_serdata_from_sample (st, SDK_DATA, sample);
  uint32_t size = ddsi_serdata_size (sd);
  unsigned char *buf = malloc (size);
  ddsi_serdata_to_ser (sd, 0, size, buf);
  ddsi_serdata_unref (sd);

  long n = 0; double t0 = now (), dt;
  do {
    for (int i = 0; i < 10; i++) {
      struct ddsi_serdata *s = ddsi_serdata_from_sample (st, SDK_DATA, sample);
      ddsi_serdata_to_ser (s, 0, size, buf);
      ddsi_serdata_unref (s);
      sink = buf[size - 1];
    }
    n += 10; dt = now () - t0;
  } while (dt < budget);
  printf ("%s,encode,c,%u,%ld,%.0f\n", name, size, n, dt * 1e9 / (double) n);

  n = 0; t0 = now ();
  do {
    for (int i = 0; i < 10; i++) {
      ddsrt_iovec_t iov = { .iov_base = buf, .iov_len = size };
      struct ddsi_serdata *s = ddsi_serdata_from_ser_iov (st, SDK_DATA, 1, &iov, size);
      ddsi_serdata_to_sample (s, kept, NULL, NULL);
      ddsi_serdata_unref (s);
    }
    n += 10; dt = now () - t0;
  } while (dt < budget);
  printf ("%s,decode,c,%u,%ld,%.0f\n", name, size, n, dt * 1e9 / (double) n);
  free (buf);
}

int main (int argc, char **argv)
{
  double budget = argc > 1 ? atof (argv[1]) : 1.0;
  dds_entity_t dp = dds_create_participant (DDS_DOMAIN_DEFAULT, NULL, NULL);
  if (dp < 0) { fprintf (stderr, "participant: %s\n", dds_strretcode (dp)); return 1; }

  sensor_msgs_msg_dds__LaserScan_ scan;
  memset (&scan, 0, sizeof scan);
  scan.header.stamp.sec = 1700000000;
  scan.header.frame_id = "base_scan";
  scan.angle_min = -3.14159f; scan.angle_max = 3.14159f;
  scan.angle_increment = 2.0f * 3.14159f / 720.0f; scan.range_max = 30.0f;
  float ranges[720];
  for (int i = 0; i < 720; i++) ranges[i] = 0.5f + (float) ((i + 1) % 97) * 0.25f;
  scan.ranges._buffer = ranges; scan.ranges._length = scan.ranges._maximum = 720;
  sensor_msgs_msg_dds__LaserScan_ *scan_kept = sensor_msgs_msg_dds__LaserScan___alloc ();
  measure (dp, "laser_scan_720", &sensor_msgs_msg_dds__LaserScan__desc, &scan, scan_kept, budget);

  nav_msgs_msg_dds__Odometry_ odom;
  memset (&odom, 0, sizeof odom);
  odom.header.frame_id = "odom"; odom.child_frame_id = "base_link";
  odom.pose.pose.position.x = 1.0; odom.pose.pose.position.y = 2.0;
  odom.pose.pose.orientation.w = 1.0;
  for (int i = 0; i < 36; i++) odom.pose.covariance[i] = i * 0.01;
  odom.twist.twist.linear.x = 0.5;
  nav_msgs_msg_dds__Odometry_ *odom_kept = nav_msgs_msg_dds__Odometry___alloc ();
  measure (dp, "odometry", &nav_msgs_msg_dds__Odometry__desc, &odom, odom_kept, budget);

  nav_msgs_msg_dds__OccupancyGrid_ grid;
  memset (&grid, 0, sizeof grid);
  grid.header.frame_id = "map"; grid.info.resolution = 0.05f;
  grid.info.width = 1000; grid.info.height = 1000;
  int8_t *cells = malloc (1000000);
  for (int i = 0; i < 1000000; i++) cells[i] = (int8_t) (((i + 1) % 3) * 50 - 1);
  grid.data._buffer = cells; grid.data._length = grid.data._maximum = 1000000;
  nav_msgs_msg_dds__OccupancyGrid_ *grid_kept = nav_msgs_msg_dds__OccupancyGrid___alloc ();
  measure (dp, "occupancy_grid_1000x1000", &nav_msgs_msg_dds__OccupancyGrid__desc, &grid,
           grid_kept, budget);
  dds_delete (dp);
  return 0;
}
