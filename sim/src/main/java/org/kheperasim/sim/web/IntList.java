package org.kheperasim.sim.web;

import java.util.Arrays;

/** A growable column of ints: one sample value after another, as the page's encoder reads them. */
final class IntList {
    private int[] values = new int[256];
    private int size;

    void add(int v) {
        if (size == values.length) {
            values = Arrays.copyOf(values, size * 2);
        }
        values[size++] = v;
    }

    int get(int i) {
        return values[i];
    }

    int size() {
        return size;
    }

    /** @return the last value, or {@code empty} when there is none */
    int last(int empty) {
        return size == 0 ? empty : values[size - 1];
    }
}
