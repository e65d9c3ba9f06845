/* pfx C ABI v1 — services a host may offer its plugins, looked up by versioned id through
 * pfx_host.get_service (since ABI 1.2). A plugin asks for what it can use and works without it:
 * every service is optional, and NULL means "not offered". A service struct follows the growth
 * rule of core.h; a changed meaning is a new id ("pfx.thread_pool/2"). */
#ifndef PFX_SERVICES_H
#define PFX_SERVICES_H

#include "pfx/core.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- Thread pool -------------------------------------------------------------------------------
 * CPU work of a plugin (an importer's parsing, a CPU reference) runs on the host's threads, so a
 * plugin never starts threads of its own in somebody else's process and never decides their
 * affinity, priority or number: the host does. Without the service a plugin runs the same work
 * serially on the calling thread. */
#define PFX_SERVICE_THREAD_POOL "pfx.thread_pool/1"

/* One task of a parallel run: index in [0, count). Must not throw, longjmp or call GL. */
typedef void (*pfx_task_fn)(void* user, uint32_t index);

typedef struct pfx_thread_pool {
  uint32_t struct_size;
  void* pool_data; /* opaque; passed back to every function */
  /* How many tasks can run at the same time (>= 1), the calling thread included. */
  uint32_t (*concurrency)(void* pool_data);
  /* Runs task(user, i) once for every i in [0, count), on the pool's threads and the calling
   * thread, and returns when every task has returned. At most max_parallel tasks run at once
   * (0: as many as concurrency()). Thread-safe: several threads may call run at once; a task may
   * call run (the nested run may execute serially).
   * The pool's promise: run completes even when none of the pool's threads is free, because the
   * calling thread takes every task no other thread has taken; it never waits for a task that no
   * thread has started. (A pool that queues the tasks and blocks the caller deadlocks as soon as a
   * task calls run while every thread is busy.)
   * The task's promise: tasks may run in any order, on any of those threads, or all one after
   * another on the calling thread, so a task must never wait for another task of the same run to
   * start or to reach a point. It may wait for work another task has already begun (a lock held,
   * an item being processed): that work finishes without any further thread. */
  void (*run)(void* pool_data, pfx_task_fn task, void* user, uint32_t count, uint32_t max_parallel);
} pfx_thread_pool;
#define PFX_THREAD_POOL_MIN_SIZE PFX_STRUCT_SIZE_THROUGH(pfx_thread_pool, run)

#ifdef __cplusplus
}
#endif
#endif /* PFX_SERVICES_H */
