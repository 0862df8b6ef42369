/* CDR encode/decode time per message of Cyclone DDS's C serializer on
 * idlc-generated types (the C side of bench/bench-typed.sh): the same
 * messages as bin/bench_typed_cdr. Debian's libddsc 0.10 does not export
 * dds_get_entity_sertype, so the sertype of a topic cannot be had; the
 * serializer itself is exported: dds_stream_write / dds_stream_read and
 * dds_stream_normalize_data driven by the idlc descriptor's m_ops, the very
 * functions Cyclone's default serdata calls per sample (from_sample: write
 * after the 4-byte header; from_ser + to_sample: normalize, i.e. check and
 * byte-swap, then read). Encode = sample -> 4-byte header + XCDR1 body,
 * padded to 4, in a kept buffer; decode = check + read into a kept sample.
 * What this leaves out of a C writer/reader: the serdata allocation and
 * reference counting around them (so C is favoured, if anything).
 *   typed_cdr_c SECONDS [DUMP-FOLDER]
 * prints "case,op,c,bytes,iterations,ns_per_msg"; with DUMP-FOLDER, writes
 * each case's encoding there as <case>.cdr (compared with the Ada ones). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "dds/dds.h"
#include "dds/ddsi/ddsi_cdrstream.h"
#include "typed_cdr.h"

#define XCDR1 1  /* CDR_ENC_VERSION_1 (dds/ddsi/q_protocol.h) */

static double now (void)
{
  struct timespec t;
  clock_gettime (CLOCK_MONOTONIC, &t);
  return (double) t.tv_sec + (double) t.tv_nsec * 1e-9;
}

static volatile unsigned char sink;
static const char *dumps;  /* folder for the encodings, or NULL */

/* Header + body + padding into buf (kept, large enough: bytes 4 .. of buf
 * are the ostream's buffer, which never grows, as in a serdata whose body
 * follows its header); returns the size. XCDR1 aligns relative to the
 * body, hence the ostream starting after the header. */
static uint32_t encode (unsigned char *buf, uint32_t capacity, const void *sample,
                        const uint32_t *ops)
{
  static const unsigned char header[4] = { 0, 1, 0, 0 };  /* CDR_LE (x86) */
  dds_ostream_t os = { .m_buffer = buf + 4, .m_size = capacity - 4, .m_index = 0,
                       .m_xcdr_version = XCDR1 };
  memcpy (buf, header, 4);
  dds_stream_write (&os, sample, ops);
  while (os.m_index % 4 != 0)
    os.m_buffer[os.m_index++] = 0;
  if (os.m_buffer != buf + 4) { fprintf (stderr, "encode: buffer too small\n"); exit (1); }
  return 4 + os.m_index;
}

/* Checks the body (as a reader does before accepting it) and reads it into
 * kept; 0 on malformed data. */
static int decode (unsigned char *buf, uint32_t size, void *kept, const uint32_t *ops)
{
  uint32_t off = 0;
  if (dds_stream_normalize_data ((char *) buf + 4, &off, size - 4, false, XCDR1, ops) == NULL)
    return 0;
  dds_istream_t is;
  dds_istream_init (&is, size - 4, buf + 4, XCDR1);
  dds_stream_read (&is, kept, ops);
  return 1;
}

static void measure (const char *name, const dds_topic_descriptor_t *desc,
                     const void *sample, void *kept, double budget)
{
  const uint32_t *ops = desc->m_ops;
  dds_ostream_t first;
  dds_ostream_init (&first, 4096, XCDR1);
  dds_stream_write (&first, sample, ops);  /* the body's size */
  uint32_t capacity = 4 + first.m_index + 4;
  dds_ostream_fini (&first);
  unsigned char *out = malloc (capacity), *buf = malloc (capacity);
  uint32_t size = encode (out, capacity, sample, ops);
  memcpy (buf, out, size);
  if (!decode (buf, size, kept, ops)) { fprintf (stderr, "%s: own encoding rejected\n", name); exit (1); }
  if (dumps != NULL) {
    char path[4096];
    snprintf (path, sizeof path, "%s/%s.cdr", dumps, name);
    FILE *f = fopen (path, "wb");
    if (f == NULL || fwrite (out, 1, size, f) != size || fclose (f) != 0) {
      fprintf (stderr, "%s: cannot write %s\n", name, path); exit (1);
    }
  }

  long n = 0; double t0 = now (), dt;
  do {
    for (int i = 0; i < 10; i++) {
      uint32_t s = encode (out, capacity, sample, ops);
      sink = out[s - 1];
    }
    n += 10; dt = now () - t0;
  } while (dt < budget);
  printf ("%s,encode,c,%u,%ld,%.0f\n", name, size, n, dt * 1e9 / (double) n);

  n = 0; t0 = now ();
  do {
    for (int i = 0; i < 10; i++)
      if (!decode (buf, size, kept, ops)) { fprintf (stderr, "decode\n"); exit (1); }
    n += 10; dt = now () - t0;
  } while (dt < budget);
  printf ("%s,decode,c,%u,%ld,%.0f\n", name, size, n, dt * 1e9 / (double) n);
  free (out);
  free (buf);
}

int main (int argc, char **argv)
{
  double budget = argc > 1 ? atof (argv[1]) : 1.0;
  dumps = argc > 2 ? argv[2] : NULL;

  sensor_msgs_msg_dds__LaserScan_ scan;
  memset (&scan, 0, sizeof scan);
  scan.header.stamp.sec = 1700000000;
  scan.header.frame_id = "base_scan";
  scan.angle_min = -3.14159f; scan.angle_max = 3.14159f;
  scan.angle_increment = 0.0087266389f;  /* the same literal as the Ada side */
  scan.range_max = 30.0f;
  float ranges[720];
  for (int i = 0; i < 720; i++) ranges[i] = 0.5f + (float) ((i + 1) % 97) * 0.25f;
  scan.ranges._buffer = ranges; scan.ranges._length = scan.ranges._maximum = 720;
  sensor_msgs_msg_dds__LaserScan_ *scan_kept = sensor_msgs_msg_dds__LaserScan___alloc ();
  measure ("laser_scan_720", &sensor_msgs_msg_dds__LaserScan__desc, &scan, scan_kept, budget);

  nav_msgs_msg_dds__Odometry_ odom;
  memset (&odom, 0, sizeof odom);
  odom.header.frame_id = "odom"; odom.child_frame_id = "base_link";
  odom.pose.pose.position.x = 1.0; odom.pose.pose.position.y = 2.0;
  odom.pose.pose.orientation.w = 1.0;
  for (int i = 0; i < 36; i++) odom.pose.covariance[i] = i * 0.01;
  odom.twist.twist.linear.x = 0.5;
  nav_msgs_msg_dds__Odometry_ *odom_kept = nav_msgs_msg_dds__Odometry___alloc ();
  measure ("odometry", &nav_msgs_msg_dds__Odometry__desc, &odom, odom_kept, budget);

  nav_msgs_msg_dds__OccupancyGrid_ grid;
  memset (&grid, 0, sizeof grid);
  grid.header.frame_id = "map"; grid.info.resolution = 0.05f;
  grid.info.width = 1000; grid.info.height = 1000;
  grid.info.origin.orientation.w = 1.0;  /* the definition's default (the Ada record has it) */
  int8_t *cells = malloc (1000000);
  for (int i = 0; i < 1000000; i++) cells[i] = (int8_t) (((i + 1) % 3) * 50 - 1);
  grid.data._buffer = cells; grid.data._length = grid.data._maximum = 1000000;
  nav_msgs_msg_dds__OccupancyGrid_ *grid_kept = nav_msgs_msg_dds__OccupancyGrid___alloc ();
  measure ("occupancy_grid_1000x1000", &nav_msgs_msg_dds__OccupancyGrid__desc, &grid,
           grid_kept, budget);
  return 0;
}
