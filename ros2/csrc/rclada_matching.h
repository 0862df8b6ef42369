/*
 * Matched-endpoint and built-in-topic queries of RCL services, clients and
 * graph (not for users: bound by RCL.DDS.Matching). See rclada_matching.c.
 */
#ifndef RCLADA_MATCHING_H
#define RCLADA_MATCHING_H

#include <stddef.h>
#include <stdint.h>
#include "dds/dds.h"

/* The value of "key" in the USER_DATA ("k1=v1;k2=v2;") of the writer
   matched by "reader" whose GUID is "guid": 1 found (value copied,
   NUL-terminated, truncated to cap - 1), 0 writer matched but no such key,
   -1 no matched writer with that GUID, < -1 a DDS error code - 1. */
int rclada_match_writer_key (dds_entity_t reader, const unsigned char guid[16],
                             const char *key, char *value, size_t cap);

/* 1 when "writer" has matched a reader whose USER_DATA has key=value,
   0 when not, < 0 a DDS error. */
int rclada_match_has_reader (dds_entity_t writer, const char *key, const char *value);

/* rmw_cyclonedds's "service is available": a reader matched by the request
   writer and a writer matched by the reply reader carry the same serviceid
   (without serviceids: both matches exist). 1 yes, 0 no, < 0 DDS error. */
int rclada_match_service_available (dds_entity_t request_writer, dds_entity_t reply_reader);

/* One endpoint (or participant) of the DDS built-in topics. */
struct rclada_endpoint {
  const char *topic_name;     /* "" for participants */
  const char *type_name;
  unsigned char key[16];      /* endpoint (or participant) GUID */
  unsigned char participant_key[16];
  int32_t reliability;        /* 0 best effort, 1 reliable, -1 unknown */
  int32_t durability;         /* 0 volatile, 1 transient local, 2 transient, 3 persistent */
  int32_t history;            /* 0 keep last, 1 keep all */
  int32_t depth;
  int64_t deadline;           /* ns, INT64_MAX when infinite */
  int64_t lifespan;
  int32_t liveliness;
  int64_t lease;
  const char *user_data;      /* NUL-terminated copy, "" when none */
};

typedef void (*rclada_endpoint_cb) (void *context, const struct rclada_endpoint *ep);

/* Calls "cb" for every alive instance of the built-in topic "which"
   (0 DCPSParticipant, 1 DCPSPublication, 2 DCPSSubscription) known to
   "participant". Returns the count, or < 0 a DDS error. */
int rclada_match_builtin (dds_entity_t participant, int which, rclada_endpoint_cb cb,
                          void *context);

#endif
