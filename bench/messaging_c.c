/*
 * The C limit of bench-messaging.sh: the same ping-pong and throughput
 * runs as the Ada and Python peers, written directly on Cyclone DDS with an
 * idlc-generated type (std_msgs/msg/UInt8MultiArray on rt/bench_*).
 *
 *   messaging_c ping SIZE COUNT   round trips; prints "rtt_us <median> <p99>"
 *   messaging_c pong              echoes rt/bench_ping to rt/bench_pong
 *   messaging_c pub SIZE SECONDS  publishes as fast as possible
 *   messaging_c sub               counts; prints "throughput <msgs/s> <MB/s>"
 * A message with layout.data_offset = 0xFFFFFFFF ends pong / sub.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "dds/dds.h"
#include "messaging.h"

#define STOP 0xFFFFFFFFu
#define CHECK(x, what) do { if ((x) < 0) { fprintf (stderr, "%s: %s\n", what, dds_strretcode (x)); exit (2); } } while (0)

typedef std_msgs_msg_dds__UInt8MultiArray_ msg_t;

static dds_entity_t pp;

/* ROS 2 default QoS (reliable, keep last 10, volatile); keep all for the
   throughput runs, so that every sample counts (flow control, no loss). */
static dds_qos_t *ros_default_qos (int keep_all)
{
  dds_qos_t *q = dds_create_qos ();
  dds_qset_reliability (q, DDS_RELIABILITY_RELIABLE, DDS_INFINITY);
  if (keep_all)
    dds_qset_history (q, DDS_HISTORY_KEEP_ALL, 0);
  else
    dds_qset_history (q, DDS_HISTORY_KEEP_LAST, 10);
  dds_qset_durability (q, DDS_DURABILITY_VOLATILE);
  dds_data_representation_id_t xcdr1 = DDS_DATA_REPRESENTATION_XCDR1;
  dds_qset_data_representation (q, 1, &xcdr1);
  return q;
}

static dds_entity_t endpoint (const char *topic_name, int writer)
{
  dds_qos_t *q = ros_default_qos (strcmp (topic_name, "rt/bench_thr") == 0);
  dds_entity_t tp = dds_create_topic (pp, &std_msgs_msg_dds__UInt8MultiArray__desc, topic_name, q, NULL);
  CHECK (tp, "topic");
  dds_entity_t e = writer ? dds_create_writer (pp, tp, q, NULL) : dds_create_reader (pp, tp, q, NULL);
  CHECK (e, "endpoint");
  dds_delete_qos (q);
  return e;
}

static void wait_matched (dds_entity_t wr)
{
  dds_publication_matched_status_t st;
  for (int i = 0; i < 2000; i++) {
    dds_get_publication_matched_status (wr, &st);
    if (st.current_count > 0) return;
    dds_sleepfor (DDS_MSECS (5));
  }
  fprintf (stderr, "no match\n");
  exit (3);
}

static void fill (msg_t *m, uint32_t size, uint32_t offset)
{
  memset (m, 0, sizeof (*m));
  m->layout.data_offset = offset;
  m->data._length = m->data._maximum = size;
  m->data._buffer = calloc (size ? size : 1, 1);
  m->data._release = true;
}

static int cmp (const void *a, const void *b)
{
  int64_t x = *(const int64_t *) a, y = *(const int64_t *) b;
  return (x > y) - (x < y);
}

/* Waits for and takes one sample (loaned); returns its data_offset. */
static uint32_t take_one (dds_entity_t rd, dds_entity_t ws)
{
  void *buf[1] = { NULL };
  dds_sample_info_t si;
  for (;;) {
    dds_return_t n = dds_take (rd, buf, &si, 1, 1);
    CHECK (n, "take");
    if (n == 1) {
      uint32_t off = ((msg_t *) buf[0])->layout.data_offset;
      int valid = si.valid_data;
      dds_return_loan (rd, buf, n);
      buf[0] = NULL;
      if (valid) return off;
    } else {
      CHECK (dds_waitset_wait (ws, NULL, 0, DDS_SECS (10)), "wait");
    }
  }
}

int main (int argc, char **argv)
{
  if (argc < 2) { fprintf (stderr, "usage: see source\n"); return 1; }
  const char *dom = getenv ("ROS_DOMAIN_ID");
  pp = dds_create_participant (dom ? (dds_domainid_t) atoi (dom) : 0, NULL, NULL);
  CHECK (pp, "participant");
  const char *mode = argv[1];
  if (strcmp (mode, "pong") == 0) {
    dds_entity_t rd = endpoint ("rt/bench_ping", 0), wr = endpoint ("rt/bench_pong", 1);
    dds_entity_t ws = dds_create_waitset (pp);
    dds_waitset_attach (ws, dds_create_readcondition (rd, DDS_ANY_STATE), 0);
    for (;;) {
      void *buf[1] = { NULL };
      dds_sample_info_t si;
      dds_return_t n = dds_take (rd, buf, &si, 1, 1);
      CHECK (n, "take");
      if (n == 0) { dds_waitset_wait (ws, NULL, 0, DDS_SECS (30)); continue; }
      int stop = si.valid_data && ((msg_t *) buf[0])->layout.data_offset == STOP;
      if (si.valid_data) CHECK (dds_write (wr, buf[0]), "write");
      dds_return_loan (rd, buf, n);
      if (stop) break;
    }
  } else if (strcmp (mode, "ping") == 0 && argc == 4) {
    uint32_t size = (uint32_t) atoi (argv[2]);
    int count = atoi (argv[3]), warm = count / 10 + 10;
    dds_entity_t wr = endpoint ("rt/bench_ping", 1), rd = endpoint ("rt/bench_pong", 0);
    dds_entity_t ws = dds_create_waitset (pp);
    dds_waitset_attach (ws, dds_create_readcondition (rd, DDS_ANY_STATE), 0);
    wait_matched (wr);
    dds_sleepfor (DDS_MSECS (300));
    msg_t m;
    fill (&m, size, 0);
    int64_t *rtt = malloc (sizeof (int64_t) * (size_t) count);
    for (int i = 0; i < warm + count; i++) {
      dds_time_t t0 = dds_time ();
      CHECK (dds_write (wr, &m), "write");
      take_one (rd, ws);
      if (i >= warm) rtt[i - warm] = dds_time () - t0;
    }
    qsort (rtt, (size_t) count, sizeof (int64_t), cmp);
    printf ("rtt_us %.2f %.2f\n", rtt[count / 2] / 1e3, rtt[(count * 99) / 100] / 1e3);
    m.layout.data_offset = STOP;
    dds_write (wr, &m);
    dds_sleepfor (DDS_MSECS (200));
  } else if (strcmp (mode, "pub") == 0 && argc == 4) {
    uint32_t size = (uint32_t) atoi (argv[2]);
    double seconds = atof (argv[3]);
    dds_entity_t wr = endpoint ("rt/bench_thr", 1);
    wait_matched (wr);
    dds_sleepfor (DDS_MSECS (300));
    msg_t m;
    fill (&m, size, 0);
    dds_time_t end = dds_time () + (dds_duration_t) (seconds * 1e9);
    long sent = 0;
    while (dds_time () < end) { CHECK (dds_write (wr, &m), "write"); sent++; }
    m.layout.data_offset = STOP;
    dds_write (wr, &m);
    dds_sleepfor (DDS_MSECS (500));
    fprintf (stderr, "sent %ld\n", sent);
  } else if (strcmp (mode, "sub") == 0) {
    dds_entity_t rd = endpoint ("rt/bench_thr", 0);
    dds_entity_t ws = dds_create_waitset (pp);
    dds_waitset_attach (ws, dds_create_readcondition (rd, DDS_ANY_STATE), 0);
    long count = 0;
    double bytes = 0;
    dds_time_t first = 0, last = 0;
    for (;;) {
      void *buf[16] = { NULL };
      dds_sample_info_t si[16];
      dds_return_t n = dds_take (rd, buf, si, 16, 16);
      CHECK (n, "take");
      if (n == 0) { CHECK (dds_waitset_wait (ws, NULL, 0, DDS_SECS (30)), "wait"); continue; }
      int stop = 0;
      for (int i = 0; i < n; i++) {
        if (!si[i].valid_data) continue;
        msg_t *m = buf[i];
        if (m->layout.data_offset == STOP) { stop = 1; continue; }
        if (count == 0) first = dds_time ();
        count++;
        bytes += m->data._length;
        last = dds_time ();
      }
      dds_return_loan (rd, buf, n);
      if (stop) break;
    }
    double secs = (last - first) / 1e9;
    if (count > 1 && secs > 0)
      printf ("throughput %.1f %.3f\n", (count - 1) / secs, bytes / secs / 1e6);
    else
      printf ("throughput 0 0\n");
  } else {
    fprintf (stderr, "bad arguments\n");
    return 1;
  }
  dds_delete (pp);
  return 0;
}
