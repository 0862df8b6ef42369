/*
 * Matched-endpoint and built-in-topic queries (see rclada_matching.h).
 * Plain Cyclone DDS 0.10 C API; nothing is retained between calls.
 */
#include <string.h>
#include <stdlib.h>
#include "rclada_matching.h"

#define MAX_MATCHES 1024

/* Copies the value of "key" from user data "ud" (size "sz") into value. */
static int user_data_key (const unsigned char *ud, size_t sz, const char *key,
                          char *value, size_t cap)
{
  size_t klen = strlen (key);
  size_t i = 0;
  while (i < sz) {
    size_t start = i, eq = (size_t) -1, end;
    while (i < sz && ud[i] != ';') {
      if (ud[i] == '=' && eq == (size_t) -1)
        eq = i;
      i++;
    }
    end = i;
    i++; /* skip ';' */
    if (eq != (size_t) -1 && eq - start == klen && memcmp (ud + start, key, klen) == 0) {
      size_t n = end - eq - 1;
      if (cap == 0)
        return 1;
      if (n > cap - 1)
        n = cap - 1;
      memcpy (value, ud + eq + 1, n);
      value[n] = 0;
      return 1;
    }
  }
  return 0;
}

static int qos_key (const dds_qos_t *qos, const char *key, char *value, size_t cap)
{
  void *ud = NULL;
  size_t sz = 0;
  int found = 0;
  if (qos != NULL && dds_qget_userdata (qos, &ud, &sz) && ud != NULL) {
    found = user_data_key ((const unsigned char *) ud, sz, key, value, cap);
  }
  dds_free (ud);
  return found;
}

int rclada_match_writer_key (dds_entity_t reader, const unsigned char guid[16],
                             const char *key, char *value, size_t cap)
{
  dds_instance_handle_t hs[MAX_MATCHES];
  dds_return_t n = dds_get_matched_publications (reader, hs, MAX_MATCHES);
  if (n < 0)
    return n - 1;
  for (int i = 0; i < n && i < MAX_MATCHES; i++) {
    dds_builtintopic_endpoint_t *ep = dds_get_matched_publication_data (reader, hs[i]);
    if (ep != NULL) {
      int result = -1;
      if (memcmp (ep->key.v, guid, 16) == 0)
        result = qos_key (ep->qos, key, value, cap);
      dds_builtintopic_free_endpoint (ep);
      if (result >= 0)
        return result;
    }
  }
  return -1;
}

int rclada_match_has_reader (dds_entity_t writer, const char *key, const char *value)
{
  dds_instance_handle_t hs[MAX_MATCHES];
  char found[256];
  dds_return_t n = dds_get_matched_subscriptions (writer, hs, MAX_MATCHES);
  if (n < 0)
    return n;
  for (int i = 0; i < n && i < MAX_MATCHES; i++) {
    dds_builtintopic_endpoint_t *ep = dds_get_matched_subscription_data (writer, hs[i]);
    if (ep != NULL) {
      int same = qos_key (ep->qos, key, found, sizeof found) && strcmp (found, value) == 0;
      dds_builtintopic_free_endpoint (ep);
      if (same)
        return 1;
    }
  }
  return 0;
}

int rclada_match_service_available (dds_entity_t request_writer, dds_entity_t reply_reader)
{
  dds_instance_handle_t rds[MAX_MATCHES], wrs[MAX_MATCHES];
  char id[256];
  int with_ids = 0;
  dds_return_t nr = dds_get_matched_subscriptions (request_writer, rds, MAX_MATCHES);
  dds_return_t nw;
  if (nr < 0)
    return nr;
  nw = dds_get_matched_publications (reply_reader, wrs, MAX_MATCHES);
  if (nw < 0)
    return nw;
  for (int i = 0; i < nr && i < MAX_MATCHES; i++) {
    dds_builtintopic_endpoint_t *rd = dds_get_matched_subscription_data (request_writer, rds[i]);
    if (rd == NULL)
      continue;
    if (qos_key (rd->qos, "serviceid", id, sizeof id)) {
      with_ids = 1;
      for (int j = 0; j < nw && j < MAX_MATCHES; j++) {
        dds_builtintopic_endpoint_t *wr = dds_get_matched_publication_data (reply_reader, wrs[j]);
        char other[256];
        int same = wr != NULL && qos_key (wr->qos, "serviceid", other, sizeof other)
          && strcmp (id, other) == 0;
        if (wr != NULL)
          dds_builtintopic_free_endpoint (wr);
        if (same) {
          dds_builtintopic_free_endpoint (rd);
          return 1;
        }
      }
    }
    dds_builtintopic_free_endpoint (rd);
  }
  if (!with_ids)
    return nr > 0 && nw > 0;
  return 0;
}

static void fill_qos (const dds_qos_t *qos, struct rclada_endpoint *out, char **ud_copy)
{
  dds_reliability_kind_t rk;
  dds_durability_kind_t dk;
  dds_history_kind_t hk;
  dds_liveliness_kind_t lk;
  dds_duration_t d;
  int32_t depth;
  void *ud = NULL;
  size_t sz = 0;
  out->reliability = -1;
  out->durability = -1;
  out->history = -1;
  out->depth = 0;
  out->deadline = DDS_INFINITY;
  out->lifespan = DDS_INFINITY;
  out->liveliness = -1;
  out->lease = DDS_INFINITY;
  *ud_copy = NULL;
  if (qos == NULL)
    return;
  if (dds_qget_reliability (qos, &rk, &d))
    out->reliability = (int32_t) rk;
  if (dds_qget_durability (qos, &dk))
    out->durability = (int32_t) dk;
  if (dds_qget_history (qos, &hk, &depth)) {
    out->history = (int32_t) hk;
    out->depth = depth;
  }
  if (dds_qget_deadline (qos, &d))
    out->deadline = d;
  if (dds_qget_lifespan (qos, &d))
    out->lifespan = d;
  if (dds_qget_liveliness (qos, &lk, &d)) {
    out->liveliness = (int32_t) lk;
    out->lease = d;
  }
  if (dds_qget_userdata (qos, &ud, &sz) && ud != NULL) {
    *ud_copy = malloc (sz + 1);
    if (*ud_copy != NULL) {
      memcpy (*ud_copy, ud, sz);
      (*ud_copy)[sz] = 0;
    }
  }
  dds_free (ud);
}

int rclada_match_builtin (dds_entity_t participant, int which, rclada_endpoint_cb cb,
                          void *context)
{
  dds_entity_t topic = which == 0 ? DDS_BUILTIN_TOPIC_DCPSPARTICIPANT
    : which == 1 ? DDS_BUILTIN_TOPIC_DCPSPUBLICATION : DDS_BUILTIN_TOPIC_DCPSSUBSCRIPTION;
  dds_entity_t rd = dds_create_reader (participant, topic, NULL, NULL);
  int count = 0;
  if (rd < 0)
    return rd;
  for (;;) {
    void *samples[64] = { NULL };
    dds_sample_info_t infos[64];
    dds_return_t n = dds_take (rd, samples, infos, 64, 64);
    if (n < 0) {
      dds_delete (rd);
      return n;
    }
    if (n == 0)
      break;
    for (int i = 0; i < n; i++) {
      struct rclada_endpoint ep;
      char *ud = NULL;
      if (!infos[i].valid_data || infos[i].instance_state != DDS_IST_ALIVE)
        continue;
      memset (&ep, 0, sizeof ep);
      if (which == 0) {
        const dds_builtintopic_participant_t *p = samples[i];
        ep.topic_name = "";
        ep.type_name = "";
        memcpy (ep.key, p->key.v, 16);
        memcpy (ep.participant_key, p->key.v, 16);
        fill_qos (p->qos, &ep, &ud);
      } else {
        const dds_builtintopic_endpoint_t *e = samples[i];
        ep.topic_name = e->topic_name != NULL ? e->topic_name : "";
        ep.type_name = e->type_name != NULL ? e->type_name : "";
        memcpy (ep.key, e->key.v, 16);
        memcpy (ep.participant_key, e->participant_key.v, 16);
        fill_qos (e->qos, &ep, &ud);
      }
      ep.user_data = ud != NULL ? ud : "";
      cb (context, &ep);
      free (ud);
      count++;
    }
    dds_return_loan (rd, samples, n);
  }
  dds_delete (rd);
  return count;
}
