/* Memory a run of the exact scene engine leaves for the next run on the same thread. A run takes a
 * few megabytes (its regions, their step tables, its peaks in doubt), and what it frees goes back to
 * the system (glibc trims the heap and unmaps large blocks), so the next run faulted the pages in
 * anew: 7 % of the assessor's house's time, where one wall's engine allocates nothing. Blocks freed
 * here are kept per thread (at most SX_POOL_BLOCKS of them and SX_POOL_BYTES in all) and handed to
 * the next request of a size they hold; a thread's blocks are freed when it ends. The house under an
 * 80-s record takes 113 blocks (16 regions, their matrices and step tables): with room for 64, the
 * other 49 went back to the heap and the next run faulted in 280 pages, 4 % of its time. Nothing a run
 * computes depends on which block it gets: the engine sets what it reads (the sanitizer build fills
 * a block handed out again with NaNs, and tests/c/test_scene_exact.c runs a scene again after
 * another for the same bits). */
#include "rw_scene_exact_internal.h"

#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#define SX_POOL_BLOCKS 256
#define SX_POOL_BYTES (64u << 20)
#define HEADER 32 /* a block's size ahead of it (a multiple of 32: the vector loads stay aligned as malloc's) */

typedef struct {
    int n;
    size_t bytes;
    unsigned char *block[SX_POOL_BLOCKS];
} pool;

static pthread_key_t pool_key;
static pthread_once_t pool_once = PTHREAD_ONCE_INIT;
static int pool_usable;

static size_t size_of(const unsigned char *block) { return *(const size_t *)(const void *)block; }

static void release(void *p)
{
    pool *P = (pool *)p;
    int k;
    for (k = 0; k < P->n; k++) free(P->block[k]);
    free(P);
}

static void make_key(void) { pool_usable = pthread_key_create(&pool_key, release) == 0; }

/* this thread's pool (NULL: none could be had: blocks then come from malloc and go back to it) */
static pool *this_pool(void)
{
    pool *P;
    pthread_once(&pool_once, make_key);
    if (!pool_usable) return NULL;
    if ((P = (pool *)pthread_getspecific(pool_key)) != NULL) return P;
    if (!(P = (pool *)calloc(1, sizeof *P))) return NULL;
    if (pthread_setspecific(pool_key, P) != 0) return free(P), NULL;
    return P;
}

void *sx_pool_alloc(size_t size)
{
    pool *P = this_pool();
    unsigned char *b;
    int k, best = -1;
    for (k = 0; P && k < P->n; k++) /* the smallest block that holds it, of at most twice its size */
        if (size_of(P->block[k]) >= size && size_of(P->block[k]) <= 2 * size &&
            (best < 0 || size_of(P->block[k]) < size_of(P->block[best])))
            best = k;
    if (best >= 0) {
        b = P->block[best];
        P->bytes -= size_of(b);
        P->block[best] = P->block[--P->n];
#ifdef RW_POOL_POISON /* (the sanitizer build: a read of what the last run left is then NaN in the results) */
        memset(b + HEADER, 0xff, size_of(b));
#endif
        return b + HEADER;
    }
    if (!(b = (unsigned char *)malloc(HEADER + size))) return NULL;
    *(size_t *)(void *)b = size;
    return b + HEADER;
}

void sx_pool_free(void *p)
{
    pool *P;
    unsigned char *b;
    if (!p) return;
    b = (unsigned char *)p - HEADER;
    P = this_pool();
    if (P && P->n < SX_POOL_BLOCKS && P->bytes + size_of(b) <= SX_POOL_BYTES) {
        P->block[P->n++] = b;
        P->bytes += size_of(b);
        return;
    }
    free(b);
}
