/*
 * The generic raw-CDR sertype of RCL (not for users: bound by RCL.DDS.Thin).
 * See rclada_raw_cdr.c.
 */
#ifndef RCLADA_RAW_CDR_H
#define RCLADA_RAW_CDR_H

#include <stdint.h>
#include "dds/dds.h"

/* The application sample of a raw-CDR topic (dds_write / dds_take only). */
struct rclada_raw_sample {
  unsigned char *data;
  uint32_t size;
};

/* What RCL needs from a dds_sample_info_t. */
struct rclada_raw_info {
  int64_t source_timestamp;    /* ns since the Unix epoch */
  uint64_t publication_handle; /* the writer's instance handle, reader-local */
};

dds_entity_t rclada_dds_create_raw_topic (dds_entity_t participant, const char *topic_name,
                                          const char *type_name, const dds_qos_t *qos,
                                          const void **sertype);
/* "sertype" receives the topic's sertype, valid while the topic exists. */

/* Writes "size" bytes of CDR (encapsulation header included); "sertype" is
   the one returned with the writer's topic. */
dds_return_t rclada_dds_write_raw (dds_entity_t writer, const void *sertype,
                                   const void *bytes, size_t size, dds_time_t timestamp);

/* Takes one valid sample: returns 1 and a serdata reference (to pass to
   rclada_dds_serdata_release), 0 when none is available, < 0 on error. */
int32_t rclada_dds_take_raw (dds_entity_t reader, void **serdata,
                             struct rclada_raw_info *info);

/* Takes up to max (1..RCLADA_TAKE_MAX) samples in one DDS take: returns how
   many valid ones it stored in serdata[0..n-1] / info[0..n-1] (each a
   reference to release), 0 when none is available, < 0 on error. */
#define RCLADA_TAKE_MAX 64
int32_t rclada_dds_take_raw_many (dds_entity_t reader, void **serdata,
                                  struct rclada_raw_info *info, int32_t max);

const unsigned char *rclada_dds_serdata_bytes (const void *serdata, uint32_t *size);
void rclada_dds_serdata_release (void *serdata);

dds_return_t rclada_dds_publication_guid (dds_entity_t reader, dds_instance_handle_t handle,
                                          unsigned char guid[16]);
dds_return_t rclada_dds_entity_guid (dds_entity_t entity, unsigned char guid[16]);

/* dds_create_participant / dds_create_domain with SIGINT and SIGTERM
   blocked in the calling thread meanwhile (Cyclone's threads inherit it). */
dds_entity_t rclada_dds_create_participant (dds_domainid_t domain, const dds_qos_t *qos);
dds_entity_t rclada_dds_create_domain (dds_domainid_t domain, const char *config);

/* Blocks SIGINT and SIGTERM in the calling thread: once the Ada runtime
   waits for them (sigwait in its interrupt server tasks), no other thread
   may take them. */
void rclada_block_stop_signals (void);

/* A serdata of "size" bytes for the topic's sertype; *buffer receives its
   storage, to be filled before rclada_dds_write_serdata (which takes the
   serdata, "used" <= size bytes of it) or rclada_dds_serdata_release. */
void *rclada_dds_serdata_new (const void *sertype, size_t size, unsigned char **buffer);
dds_return_t rclada_dds_write_serdata (dds_entity_t writer, void *serdata, size_t used,
                                       dds_time_t timestamp);

#endif
