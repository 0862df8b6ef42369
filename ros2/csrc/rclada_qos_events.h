/*
 * QoS event statuses of a writer or a reader (not for users: bound by
 * RCL.DDS), read with Cyclone's status getters, which reset the "change"
 * counts: each poll reports what happened since the previous one.
 */
#ifndef RCLADA_QOS_EVENTS_H
#define RCLADA_QOS_EVENTS_H

#include <stdint.h>
#include "dds/dds.h"

struct rclada_qos_events {
  uint32_t deadline_total;        int32_t deadline_change;
  uint32_t incompatible_total;    int32_t incompatible_change;   uint32_t last_policy;
  uint32_t liveliness_lost_total; int32_t liveliness_lost_change;    /* writer */
  uint32_t alive_count;           uint32_t not_alive_count;          /* reader */
  int32_t alive_change;           int32_t not_alive_change;
  uint32_t lost_total;            int32_t lost_change;               /* reader */
  uint32_t matched_total;         int32_t matched_change;
  uint32_t matched_current;       int32_t matched_current_change;
};

/* 0, or a negative DDS return code. */
int rclada_poll_writer_events (dds_entity_t writer, struct rclada_qos_events *e);
int rclada_poll_reader_events (dds_entity_t reader, struct rclada_qos_events *e);

#endif
