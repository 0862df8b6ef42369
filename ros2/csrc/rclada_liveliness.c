/* Liveliness tracking of matched writers: see rclada_liveliness.h. */
#include <stdlib.h>
#include <string.h>
#include <pthread.h>
#include "rclada_liveliness.h"

#define RCLADA_LIVELINESS_CAPACITY 1024
#define RCLADA_LIVELINESS_KNOWN 256

struct known_writer {
  dds_instance_handle_t handle;
  unsigned char guid[16];
};

struct change {
  unsigned char guid[16];
  int alive;
};

struct rclada_liveliness_tracker {
  pthread_mutex_t lock;
  struct change queue[RCLADA_LIVELINESS_CAPACITY];
  unsigned head;     /* index of the oldest change */
  unsigned count;
  unsigned dropped;
  struct known_writer known[RCLADA_LIVELINESS_KNOWN];
  unsigned known_count;
  unsigned known_next;   /* slot replaced next when the table is full */
  dds_listener_t *listener;
};

/* The GUID of a writer seen before (a deleted writer is no longer
   matched when its last change is reported): 1 found, 0 not. The caller
   holds t->lock (the listener's thread and rclada_liveliness_attach both
   use the table). */
static int known_guid_locked (struct rclada_liveliness_tracker *t,
                              dds_instance_handle_t handle, unsigned char guid[16])
{
  unsigned i;
  for (i = 0; i < t->known_count; i++) {
    if (t->known[i].handle == handle) {
      memcpy (guid, t->known[i].guid, 16);
      return 1;
    }
  }
  return 0;
}

static int known_guid (struct rclada_liveliness_tracker *t, dds_instance_handle_t handle,
                       unsigned char guid[16])
{
  int found;
  pthread_mutex_lock (&t->lock);
  found = known_guid_locked (t, handle, guid);
  pthread_mutex_unlock (&t->lock);
  return found;
}

static void remember (struct rclada_liveliness_tracker *t, dds_instance_handle_t handle,
                      const unsigned char guid[16])
{
  unsigned char unused[16];
  struct known_writer *k;
  pthread_mutex_lock (&t->lock);
  if (!known_guid_locked (t, handle, unused)) {
    if (t->known_count < RCLADA_LIVELINESS_KNOWN) {
      k = &t->known[t->known_count++];
    } else {
      k = &t->known[t->known_next];
      t->known_next = (t->known_next + 1) % RCLADA_LIVELINESS_KNOWN;
    }
    k->handle = handle;
    memcpy (k->guid, guid, 16);
  }
  pthread_mutex_unlock (&t->lock);
}

static void push (struct rclada_liveliness_tracker *t, const unsigned char guid[16], int alive)
{
  pthread_mutex_lock (&t->lock);
  if (t->count == RCLADA_LIVELINESS_CAPACITY) {
    t->dropped++;
  } else {
    struct change *c = &t->queue[(t->head + t->count) % RCLADA_LIVELINESS_CAPACITY];
    memcpy (c->guid, guid, 16);
    c->alive = alive;
    t->count++;
  }
  pthread_mutex_unlock (&t->lock);
}

static void on_liveliness_changed (dds_entity_t reader,
                                   const dds_liveliness_changed_status_t status, void *arg)
{
  struct rclada_liveliness_tracker *t = arg;
  unsigned char guid[16];
  dds_builtintopic_endpoint_t *writer;
  if (status.alive_count_change == 0 && status.not_alive_count_change == 0)
    return;
  /* The writer is still matched when its lease expires; when it was
     deleted it may not be any more: its GUID then comes from the table of
     writers seen before, or is reported as zero. */
  writer = dds_get_matched_publication_data (reader, status.last_publication_handle);
  if (writer != NULL) {
    memcpy (guid, writer->key.v, 16);
    dds_builtintopic_free_endpoint (writer);
    remember (t, status.last_publication_handle, guid);
  } else if (!known_guid (t, status.last_publication_handle, guid)) {
    memset (guid, 0, 16);
  }
  push (t, guid, status.alive_count_change > 0 ? 1 : 0);
}

/* The changes a reader's status accumulated before the listener was set
   reach the listener only with the next change, summed with it: a writer
   that died after three others had become alive unseen then came as
   "alive_count_change = +2", read as alive (a team saw a killed robot lost
   only when its participant's 10 s lease deleted the writer). So the
   accumulated changes are discarded (reading the status resets them) and
   every writer matched at that point is reported alive, with its GUID
   remembered for its later changes. A change between the two steps is
   either seen by the listener or covered by the enumeration (a writer
   matched then is reported alive; one lost in that window is reported when
   DDS deletes it). */
static void seed_matched_writers (dds_entity_t reader, struct rclada_liveliness_tracker *t)
{
  dds_liveliness_changed_status_t discarded;
  dds_instance_handle_t handles[RCLADA_LIVELINESS_KNOWN];
  dds_return_t n, i;
  (void) dds_get_liveliness_changed_status (reader, &discarded);
  n = dds_get_matched_publications (reader, handles, RCLADA_LIVELINESS_KNOWN);
  if (n > (dds_return_t) RCLADA_LIVELINESS_KNOWN)
    n = RCLADA_LIVELINESS_KNOWN;
  for (i = 0; i < n; i++) {
    dds_builtintopic_endpoint_t *writer = dds_get_matched_publication_data (reader, handles[i]);
    if (writer != NULL) {
      remember (t, handles[i], writer->key.v);
      push (t, writer->key.v, 1);
      dds_builtintopic_free_endpoint (writer);
    }
  }
}

struct rclada_liveliness_tracker *rclada_liveliness_attach (dds_entity_t reader)
{
  struct rclada_liveliness_tracker *t = calloc (1, sizeof *t);
  if (t == NULL)
    return NULL;
  pthread_mutex_init (&t->lock, NULL);
  t->listener = dds_create_listener (t);
  if (t->listener == NULL) {
    pthread_mutex_destroy (&t->lock);
    free (t);
    return NULL;
  }
  dds_lset_liveliness_changed (t->listener, on_liveliness_changed);
  if (dds_set_listener (reader, t->listener) < 0) {
    dds_delete_listener (t->listener);
    pthread_mutex_destroy (&t->lock);
    free (t);
    return NULL;
  }
  seed_matched_writers (reader, t);
  return t;
}

int rclada_liveliness_take (struct rclada_liveliness_tracker *t, unsigned char guid[16],
                            int *alive)
{
  int found = 0;
  pthread_mutex_lock (&t->lock);
  if (t->count > 0) {
    struct change *c = &t->queue[t->head];
    memcpy (guid, c->guid, 16);
    *alive = c->alive;
    t->head = (t->head + 1) % RCLADA_LIVELINESS_CAPACITY;
    t->count--;
    found = 1;
  }
  pthread_mutex_unlock (&t->lock);
  return found;
}

unsigned rclada_liveliness_dropped (struct rclada_liveliness_tracker *t)
{
  unsigned n;
  pthread_mutex_lock (&t->lock);
  n = t->dropped;
  pthread_mutex_unlock (&t->lock);
  return n;
}

void rclada_liveliness_detach (dds_entity_t reader, struct rclada_liveliness_tracker *t)
{
  /* Cyclone waits for a running listener call to finish before
     dds_set_listener returns, so the tracker is no longer used after it. */
  (void) dds_set_listener (reader, NULL);
  dds_delete_listener (t->listener);
  pthread_mutex_destroy (&t->lock);
  free (t);
}
