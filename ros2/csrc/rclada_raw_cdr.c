/*
 * A generic "raw CDR" sertype/serdata for Cyclone DDS 0.10 (not for users:
 * bound by RCL.DDS.Thin).
 *
 * One implementation serves every ROS 2 message type: a sertype is keyed by
 * the DDS type name only (e.g. "std_msgs::msg::dds_::String_"), has no key
 * fields (topic kind NO_KEY), offers XCDR1 only and publishes no XTypes type
 * information, so matching with other ROS 2 participants is by type name, as
 * rmw_cyclonedds does. A serdata is just the serialized bytes, including the
 * 4-byte encapsulation header: the Ada side does all (de)serialization.
 *
 * The application-level "sample" of this sertype (used only by dds_write /
 * dds_take, which RCL does not use itself) is a rclada_raw_sample: a pointer
 * to the CDR bytes and their count.
 */
#include <stdlib.h>
#include <string.h>
#include <stdint.h>

#include "dds/dds.h"
#include "dds/ddsrt/heap.h"
#include "dds/ddsi/ddsi_sertype.h"
#include "dds/ddsi/ddsi_serdata.h"
#include "dds/ddsi/q_radmin.h"

#include "rclada_raw_cdr.h"

struct raw_sertype {
  struct ddsi_sertype c;
};

struct raw_serdata {
  struct ddsi_serdata c;
  uint32_t size;      /* bytes of CDR, encapsulation header included */
  unsigned char *data;/* allocated to size rounded up to 4, zero padded */
};

static uint32_t align4 (uint32_t n)
{
  return (n + 3u) & ~3u;
}

/* ------------------------------------------------------------------ */
/* serdata                                                            */

static struct raw_serdata *raw_serdata_new (const struct ddsi_sertype *type,
                                            enum ddsi_serdata_kind kind,
                                            size_t size)
{
  struct raw_serdata *d;
  if (size > UINT32_MAX - 4u)
    return NULL;
  d = ddsrt_malloc_s (sizeof (*d));
  if (d == NULL)
    return NULL;
  ddsi_serdata_init (&d->c, type, kind);
  d->size = (uint32_t) size;
  d->data = NULL;
  if (size > 0) {
    uint32_t alloc = align4 ((uint32_t) size);
    d->data = ddsrt_malloc_s (alloc);
    if (d->data == NULL) {
      ddsrt_free (d);
      return NULL;
    }
    memset (d->data + size, 0, alloc - size);
  }
  return d;
}

static bool raw_serdata_eqkey (const struct ddsi_serdata *a, const struct ddsi_serdata *b)
{
  (void) a; (void) b;
  return true; /* no key fields: one instance */
}

static uint32_t raw_serdata_size (const struct ddsi_serdata *dcmn)
{
  const struct raw_serdata *d = (const struct raw_serdata *) dcmn;
  return d->size;
}

static void raw_serdata_free (struct ddsi_serdata *dcmn)
{
  struct raw_serdata *d = (struct raw_serdata *) dcmn;
  ddsrt_free (d->data);
  ddsrt_free (d);
}

static struct ddsi_serdata *raw_serdata_from_ser (const struct ddsi_sertype *type,
                                                  enum ddsi_serdata_kind kind,
                                                  const struct nn_rdata *fragchain,
                                                  size_t size)
{
  struct raw_serdata *d = raw_serdata_new (type, kind, size);
  uint32_t off = 0;
  if (d == NULL)
    return NULL;
  /* Fragments may overlap: copy only the part of each one beyond "off". */
  while (fragchain != NULL && off < size) {
    if (fragchain->maxp1 > off) {
      const unsigned char *payload =
        NN_RMSG_PAYLOADOFF (fragchain->rmsg, NN_RDATA_PAYLOAD_OFF (fragchain));
      uint32_t end = fragchain->maxp1 < size ? fragchain->maxp1 : (uint32_t) size;
      memcpy (d->data + off, payload + (off - fragchain->min), end - off);
      off = end;
    }
    fragchain = fragchain->nextfrag;
  }
  if (off < size)
    memset (d->data + off, 0, size - off); /* never expose stale heap bytes */
  return &d->c;
}

static struct ddsi_serdata *raw_serdata_from_ser_iov (const struct ddsi_sertype *type,
                                                      enum ddsi_serdata_kind kind,
                                                      ddsrt_msg_iovlen_t niov,
                                                      const ddsrt_iovec_t *iov,
                                                      size_t size)
{
  struct raw_serdata *d = raw_serdata_new (type, kind, size);
  size_t off = 0;
  if (d == NULL)
    return NULL;
  for (ddsrt_msg_iovlen_t i = 0; i < niov && off < size; i++) {
    size_t n = iov[i].iov_len;
    if (n > size - off)
      n = size - off;
    memcpy (d->data + off, iov[i].iov_base, n);
    off += n;
  }
  if (off < size)
    memset (d->data + off, 0, size - off);
  return &d->c;
}

static struct ddsi_serdata *raw_serdata_from_keyhash (const struct ddsi_sertype *type,
                                                      const struct ddsi_keyhash *keyhash)
{
  (void) keyhash;
  struct raw_serdata *d = raw_serdata_new (type, SDK_KEY, 0);
  return d ? &d->c : NULL;
}

static struct ddsi_serdata *raw_serdata_from_sample (const struct ddsi_sertype *type,
                                                     enum ddsi_serdata_kind kind,
                                                     const void *sample)
{
  const struct rclada_raw_sample *s = sample;
  struct raw_serdata *d;
  if (kind != SDK_DATA) {
    d = raw_serdata_new (type, kind, 0);
  } else {
    d = raw_serdata_new (type, kind, s->size);
    if (d != NULL && s->size > 0)
      memcpy (d->data, s->data, s->size);
  }
  return d ? &d->c : NULL;
}

static struct ddsi_serdata *raw_serdata_to_untyped (const struct ddsi_serdata *dcmn)
{
  struct raw_serdata *d = raw_serdata_new (dcmn->type, SDK_KEY, 0);
  if (d == NULL)
    return NULL;
  d->c.type = NULL;
  return &d->c;
}

static void raw_serdata_to_ser (const struct ddsi_serdata *dcmn, size_t off, size_t sz,
                                void *buf)
{
  const struct raw_serdata *d = (const struct raw_serdata *) dcmn;
  memcpy (buf, d->data + off, sz);
}

static struct ddsi_serdata *raw_serdata_to_ser_ref (const struct ddsi_serdata *dcmn,
                                                    size_t off, size_t sz,
                                                    ddsrt_iovec_t *ref)
{
  const struct raw_serdata *d = (const struct raw_serdata *) dcmn;
  ref->iov_base = d->data + off;
  ref->iov_len = (ddsrt_iov_len_t) sz;
  return ddsi_serdata_ref (dcmn);
}

static void raw_serdata_to_ser_unref (struct ddsi_serdata *dcmn, const ddsrt_iovec_t *ref)
{
  (void) ref;
  ddsi_serdata_unref (dcmn);
}

static bool raw_serdata_to_sample (const struct ddsi_serdata *dcmn, void *sample,
                                   void **bufptr, void *buflim)
{
  const struct raw_serdata *d = (const struct raw_serdata *) dcmn;
  struct rclada_raw_sample *s = sample;
  (void) bufptr; (void) buflim;
  if (d->c.kind != SDK_DATA)
    return true;
  ddsrt_free (s->data);
  s->data = NULL;
  s->size = 0;
  if (d->size > 0) {
    s->data = ddsrt_malloc_s (d->size);
    if (s->data == NULL)
      return false;
    memcpy (s->data, d->data, d->size);
    s->size = d->size;
  }
  return true;
}

static bool raw_serdata_untyped_to_sample (const struct ddsi_sertype *type,
                                           const struct ddsi_serdata *d, void *sample,
                                           void **bufptr, void *buflim)
{
  (void) type; (void) d; (void) sample; (void) bufptr; (void) buflim;
  return true; /* no key fields */
}

static size_t raw_serdata_print (const struct ddsi_sertype *type,
                                 const struct ddsi_serdata *dcmn, char *buf, size_t size)
{
  const struct raw_serdata *d = (const struct raw_serdata *) dcmn;
  (void) type;
  return (size_t) snprintf (buf, size, "<%u raw CDR bytes>", (unsigned) d->size);
}

static void raw_serdata_get_keyhash (const struct ddsi_serdata *d, struct ddsi_keyhash *buf,
                                     bool force_md5)
{
  (void) d; (void) force_md5;
  memset (buf, 0, sizeof (*buf));
}

static const struct ddsi_serdata_ops raw_serdata_ops = {
  .eqkey = raw_serdata_eqkey,
  .get_size = raw_serdata_size,
  .from_ser = raw_serdata_from_ser,
  .from_ser_iov = raw_serdata_from_ser_iov,
  .from_keyhash = raw_serdata_from_keyhash,
  .from_sample = raw_serdata_from_sample,
  .to_ser = raw_serdata_to_ser,
  .to_ser_ref = raw_serdata_to_ser_ref,
  .to_ser_unref = raw_serdata_to_ser_unref,
  .to_sample = raw_serdata_to_sample,
  .to_untyped = raw_serdata_to_untyped,
  .untyped_to_sample = raw_serdata_untyped_to_sample,
  .free = raw_serdata_free,
  .print = raw_serdata_print,
  .get_keyhash = raw_serdata_get_keyhash
};

/* ------------------------------------------------------------------ */
/* sertype                                                            */

static void raw_sertype_free (struct ddsi_sertype *tpcmn)
{
  ddsi_sertype_fini (tpcmn);
  ddsrt_free (tpcmn);
}

static void raw_sertype_zero_samples (const struct ddsi_sertype *tp, void *samples,
                                      size_t count)
{
  (void) tp;
  memset (samples, 0, count * sizeof (struct rclada_raw_sample));
}

static void raw_sertype_realloc_samples (void **ptrs, const struct ddsi_sertype *tp, void *old,
                                         size_t oldcount, size_t count)
{
  struct rclada_raw_sample *s;
  (void) tp;
  s = ddsrt_realloc (old, count * sizeof (*s));
  if (s != NULL && count > oldcount)
    memset (s + oldcount, 0, (count - oldcount) * sizeof (*s));
  for (size_t i = 0; i < count; i++)
    ptrs[i] = s ? &s[i] : NULL;
}

static void raw_sertype_free_samples (const struct ddsi_sertype *tp, void **ptrs, size_t count,
                                      dds_free_op_t op)
{
  (void) tp;
  if (count == 0 || ptrs == NULL)
    return;
  if (op & DDS_FREE_CONTENTS_BIT) {
    for (size_t i = 0; i < count; i++) {
      struct rclada_raw_sample *s = ptrs[i];
      ddsrt_free (s->data);
      s->data = NULL;
      s->size = 0;
    }
  }
  if (op & DDS_FREE_ALL_BIT)
    ddsrt_free (ptrs[0]);
}

static bool raw_sertype_equal (const struct ddsi_sertype *a, const struct ddsi_sertype *b)
{
  /* The generic code has already compared the type names and the ops. */
  (void) a; (void) b;
  return true;
}

static uint32_t raw_sertype_hash (const struct ddsi_sertype *tp)
{
  (void) tp;
  return 0x5a4c7a11u;
}

static size_t raw_sertype_get_serialized_size (const struct ddsi_sertype *type,
                                               const void *sample)
{
  const struct rclada_raw_sample *s = sample;
  (void) type;
  return s->size;
}

static bool raw_sertype_serialize_into (const struct ddsi_sertype *type, const void *sample,
                                        void *dst_buffer, size_t dst_size)
{
  const struct rclada_raw_sample *s = sample;
  (void) type;
  if (dst_size < s->size)
    return false;
  memcpy (dst_buffer, s->data, s->size);
  return true;
}

static const struct ddsi_sertype_ops raw_sertype_ops = {
  .version = ddsi_sertype_v0,
  .arg = NULL,
  .free = raw_sertype_free,
  .zero_samples = raw_sertype_zero_samples,
  .realloc_samples = raw_sertype_realloc_samples,
  .free_samples = raw_sertype_free_samples,
  .equal = raw_sertype_equal,
  .hash = raw_sertype_hash,
  .type_id = NULL,       /* no XTypes type information */
  .type_map = NULL,
  .type_info = NULL,
  .derive_sertype = NULL,
  .get_serialized_size = raw_sertype_get_serialized_size,
  .serialize_into = raw_sertype_serialize_into
};

/* ------------------------------------------------------------------ */
/* entry points                                                       */

dds_entity_t rclada_dds_create_raw_topic (dds_entity_t participant, const char *topic_name,
                                          const char *type_name, const dds_qos_t *qos,
                                          const void **sertype)
{
  struct raw_sertype *st = ddsrt_malloc_s (sizeof (*st));
  struct ddsi_sertype *stcmn;
  dds_entity_t topic;
  if (st == NULL)
    return DDS_RETCODE_OUT_OF_RESOURCES;
  ddsi_sertype_init_flags (&st->c, type_name, &raw_sertype_ops, &raw_serdata_ops,
                           DDSI_SERTYPE_FLAG_TOPICKIND_NO_KEY);
  st->c.allowed_data_representation = DDS_DATA_REPRESENTATION_FLAG_XCDR1;
  stcmn = &st->c;
  topic = dds_create_topic_sertype (participant, topic_name, &stcmn, qos, NULL, NULL);
  if (topic < 0) {
    /* Not registered: still ours to free. */
    raw_sertype_free (&st->c);
  }
  /* On success stcmn may point to an equal, already registered sertype, in
     which case Cyclone has freed ours; it lives as long as the topic. */
  *sertype = (topic < 0) ? NULL : stcmn;
  return topic;
}

dds_return_t rclada_dds_write_raw (dds_entity_t writer, const void *sertype,
                                   const void *bytes, size_t size, dds_time_t timestamp)
{
  const struct ddsi_sertype *type = sertype;
  struct ddsi_serdata *sd;
  ddsrt_iovec_t iov;
  if (size > UINT32_MAX - 4u)
    return DDS_RETCODE_BAD_PARAMETER;
  iov.iov_base = (void *) bytes;
  iov.iov_len = (ddsrt_iov_len_t) size;
  sd = ddsi_serdata_from_ser_iov (type, SDK_DATA, 1, &iov, size);
  if (sd == NULL)
    return DDS_RETCODE_OUT_OF_RESOURCES;
  sd->timestamp.v = timestamp;
  return dds_writecdr (writer, sd); /* consumes the reference */
}

int32_t rclada_dds_take_raw (dds_entity_t reader, void **serdata, struct rclada_raw_info *info)
{
  struct ddsi_serdata *sd = NULL;
  dds_sample_info_t si;
  dds_return_t n;
  *serdata = NULL;
  for (;;) {
    n = dds_takecdr (reader, &sd, 1, &si, DDS_ANY_STATE);
    if (n <= 0)
      return n;
    if (si.valid_data)
      break;
    ddsi_serdata_unref (sd); /* an instance state change: nothing to deliver */
  }
  *serdata = sd;
  info->source_timestamp = si.source_timestamp;
  info->publication_handle = si.publication_handle;
  return 1;
}

int32_t rclada_dds_take_raw_many (dds_entity_t reader, void **serdata,
                                  struct rclada_raw_info *info, int32_t max)
{
  struct ddsi_serdata *sd[RCLADA_TAKE_MAX];
  dds_sample_info_t si[RCLADA_TAKE_MAX];
  dds_return_t n;
  int32_t i, valid;
  if (max < 1 || max > RCLADA_TAKE_MAX)
    return DDS_RETCODE_BAD_PARAMETER;
  for (;;) {
    n = dds_takecdr (reader, sd, (uint32_t) max, si, DDS_ANY_STATE);
    if (n <= 0)
      return n;
    valid = 0;
    for (i = 0; i < n; i++) {
      if (si[i].valid_data) {
        serdata[valid] = sd[i];
        info[valid].source_timestamp = si[i].source_timestamp;
        info[valid].publication_handle = si[i].publication_handle;
        valid++;
      } else {
        ddsi_serdata_unref (sd[i]); /* an instance state change: nothing to deliver */
      }
    }
    if (valid > 0)
      return valid;
  }
}

const unsigned char *rclada_dds_serdata_bytes (const void *serdata, uint32_t *size)
{
  const struct raw_serdata *d = serdata;
  *size = d->size;
  return d->data;
}

void rclada_dds_serdata_release (void *serdata)
{
  if (serdata != NULL)
    ddsi_serdata_unref (serdata);
}

dds_return_t rclada_dds_publication_guid (dds_entity_t reader, dds_instance_handle_t handle,
                                          unsigned char guid[16])
{
  dds_builtintopic_endpoint_t *ep = dds_get_matched_publication_data (reader, handle);
  if (ep == NULL)
    return DDS_RETCODE_PRECONDITION_NOT_MET;
  memcpy (guid, ep->key.v, 16);
  dds_builtintopic_free_endpoint (ep);
  return DDS_RETCODE_OK;
}

dds_return_t rclada_dds_entity_guid (dds_entity_t entity, unsigned char guid[16])
{
  dds_guid_t g;
  dds_return_t rc = dds_get_guid (entity, &g);
  if (rc == DDS_RETCODE_OK)
    memcpy (guid, g.v, 16);
  return rc;
}

/* ------------------------------------------------------------------ */
/* Participant and domain creation with SIGINT/SIGTERM blocked, so that
   the threads Cyclone starts inherit a mask that leaves these signals to
   the Ada runtime's interrupt handling (RCL.Contexts). */

#include <signal.h>
#include <pthread.h>

static void block_stop_signals (sigset_t *old)
{
  sigset_t set;
  sigemptyset (&set);
  sigaddset (&set, SIGINT);
  sigaddset (&set, SIGTERM);
  pthread_sigmask (SIG_BLOCK, &set, old);
}

void rclada_block_stop_signals (void)
{
  sigset_t old;
  block_stop_signals (&old);
}

dds_entity_t rclada_dds_create_participant (dds_domainid_t domain, const dds_qos_t *qos)
{
  sigset_t old;
  dds_entity_t result;
  block_stop_signals (&old);
  result = dds_create_participant (domain, qos, NULL);
  pthread_sigmask (SIG_SETMASK, &old, NULL);
  return result;
}

dds_entity_t rclada_dds_create_domain (dds_domainid_t domain, const char *config)
{
  sigset_t old;
  dds_entity_t result;
  block_stop_signals (&old);
  result = dds_create_domain (domain, config);
  pthread_sigmask (SIG_SETMASK, &old, NULL);
  return result;
}

/* ------------------------------------------------------------------ */
/* Writing without an intermediate buffer: the caller serializes straight
   into a new serdata's storage. */

void *rclada_dds_serdata_new (const void *sertype, size_t size, unsigned char **buffer)
{
  struct raw_serdata *d = raw_serdata_new (sertype, SDK_DATA, size);
  if (d == NULL) {
    *buffer = NULL;
    return NULL;
  }
  *buffer = d->data;
  return d;
}

dds_return_t rclada_dds_write_serdata (dds_entity_t writer, void *serdata, size_t used,
                                       dds_time_t timestamp)
{
  struct raw_serdata *d = serdata;
  if (used < d->size) {
    /* Shrink: keep the bytes up to the next multiple of 4 zeroed. */
    memset (d->data + used, 0, align4 (d->size) - used);
    d->size = (uint32_t) used;
  }
  d->c.timestamp.v = timestamp;
  return dds_writecdr (writer, &d->c); /* consumes the reference */
}
