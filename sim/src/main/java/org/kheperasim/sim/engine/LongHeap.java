package org.kheperasim.sim.engine;

import java.util.Arrays;

/** A min-heap of longs without boxing: the crowd's pending samples, each a tick and a robot packed in one key. */
final class LongHeap {
    private long[] keys = new long[16];
    private int size;

    boolean isEmpty() {
        return size == 0;
    }

    void clear() {
        size = 0;
    }

    void push(long key) {
        if (size == keys.length) {
            keys = Arrays.copyOf(keys, size * 2);
        }
        int i = size++;
        while (i > 0) {
            int parent = (i - 1) >>> 1;
            if (keys[parent] <= key) {
                break;
            }
            keys[i] = keys[parent];
            i = parent;
        }
        keys[i] = key;
    }

    /** @return the smallest key, removed */
    long pop() {
        long top = keys[0];
        long last = keys[--size];
        int i = 0;
        while (true) {
            int child = 2 * i + 1;
            if (child >= size) {
                break;
            }
            if (child + 1 < size && keys[child + 1] < keys[child]) {
                child++;
            }
            if (keys[child] >= last) {
                break;
            }
            keys[i] = keys[child];
            i = child;
        }
        keys[i] = last;
        return top;
    }
}
