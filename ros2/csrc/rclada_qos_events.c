/* QoS event statuses: see rclada_qos_events.h. */
#include <string.h>
#include "rclada_qos_events.h"

int rclada_poll_writer_events (dds_entity_t writer, struct rclada_qos_events *e)
{
  dds_offered_deadline_missed_status_t d;
  dds_offered_incompatible_qos_status_t q;
  dds_liveliness_lost_status_t l;
  dds_publication_matched_status_t m;
  int rc;
  memset (e, 0, sizeof *e);
  if ((rc = dds_get_offered_deadline_missed_status (writer, &d)) < 0) return rc;
  if ((rc = dds_get_offered_incompatible_qos_status (writer, &q)) < 0) return rc;
  if ((rc = dds_get_liveliness_lost_status (writer, &l)) < 0) return rc;
  if ((rc = dds_get_publication_matched_status (writer, &m)) < 0) return rc;
  e->deadline_total = d.total_count;       e->deadline_change = d.total_count_change;
  e->incompatible_total = q.total_count;   e->incompatible_change = q.total_count_change;
  e->last_policy = q.last_policy_id;
  e->liveliness_lost_total = l.total_count; e->liveliness_lost_change = l.total_count_change;
  e->matched_total = m.total_count;        e->matched_change = m.total_count_change;
  e->matched_current = m.current_count;    e->matched_current_change = m.current_count_change;
  return 0;
}

int rclada_poll_reader_events (dds_entity_t reader, struct rclada_qos_events *e)
{
  dds_requested_deadline_missed_status_t d;
  dds_requested_incompatible_qos_status_t q;
  dds_liveliness_changed_status_t l;
  dds_sample_lost_status_t s;
  dds_subscription_matched_status_t m;
  int rc;
  memset (e, 0, sizeof *e);
  if ((rc = dds_get_requested_deadline_missed_status (reader, &d)) < 0) return rc;
  if ((rc = dds_get_requested_incompatible_qos_status (reader, &q)) < 0) return rc;
  if ((rc = dds_get_liveliness_changed_status (reader, &l)) < 0) return rc;
  if ((rc = dds_get_sample_lost_status (reader, &s)) < 0) return rc;
  if ((rc = dds_get_subscription_matched_status (reader, &m)) < 0) return rc;
  e->deadline_total = d.total_count;       e->deadline_change = d.total_count_change;
  e->incompatible_total = q.total_count;   e->incompatible_change = q.total_count_change;
  e->last_policy = q.last_policy_id;
  e->alive_count = l.alive_count;          e->not_alive_count = l.not_alive_count;
  e->alive_change = l.alive_count_change;  e->not_alive_change = l.not_alive_count_change;
  e->lost_total = s.total_count;           e->lost_change = s.total_count_change;
  e->matched_total = m.total_count;        e->matched_change = m.total_count_change;
  e->matched_current = m.current_count;    e->matched_current_change = m.current_count_change;
  return 0;
}
