package org.kheperasim.sim.engine.link;

/** A FIFO of commands in flight on the simulated serial line, allocation-free once grown. */
final class CommandQueue {
    static final int SPEED = 0;
    static final int POSITION = 1;
    static final int ARM = 2;
    static final int FINGERS = 3;

    private long[] time = new long[16];
    private int[] type = new int[16];
    private int[] a = new int[16];
    private int[] b = new int[16];
    private int head;
    private int size;

    void add(long t, int kind, int va, int vb) {
        if (size == time.length) {
            grow();
        }
        int i = (head + size) % time.length;
        time[i] = t;
        type[i] = kind;
        a[i] = va;
        b[i] = vb;
        size++;
    }

    private void grow() {
        int n = time.length * 2;
        long[] t2 = new long[n];
        int[] ty2 = new int[n];
        int[] a2 = new int[n];
        int[] b2 = new int[n];
        for (int k = 0; k < size; k++) {
            int i = (head + k) % time.length;
            t2[k] = time[i];
            ty2[k] = type[i];
            a2[k] = a[i];
            b2[k] = b[i];
        }
        time = t2;
        type = ty2;
        a = a2;
        b = b2;
        head = 0;
    }

    int size() {
        return size;
    }

    /** @return when the oldest command arrives, ns; {@link Long#MAX_VALUE} when none is in flight */
    long headTime() {
        return size == 0 ? Long.MAX_VALUE : time[head];
    }

    int headType() {
        return type[head];
    }

    int headA() {
        return a[head];
    }

    int headB() {
        return b[head];
    }

    void pop() {
        head = (head + 1) % time.length;
        size--;
    }

    void clear() {
        size = 0;
    }
}
