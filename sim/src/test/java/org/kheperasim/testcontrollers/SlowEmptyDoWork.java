package org.kheperasim.testcontrollers;

import java.util.Arrays;
import org.kheperasim.api.Controller;

/**
 * A doWork() that works hard and returns without a robot call (a student's planner that never reads a
 * sensor): each round sorts {@code n} numbers (parameter {@code n}), hundreds of milliseconds of real
 * time, as an empty doWork() looks on a machine that runs its thread once in a while.
 */
public class SlowEmptyDoWork extends Controller {
    private double[] numbers;

    @Override
    protected void doWork() {
        if (numbers == null) {
            numbers = new double[(int) parameters().get("n", 1_000_000)];
        }
        fillAndSort(numbers);
    }

    /** @param a filled with a fixed scramble, then sorted (the test times the same work) */
    public static void fillAndSort(double[] a) {
        Arrays.setAll(a, i -> (i * 2_654_435_761L) % 1_000_003);
        Arrays.sort(a);
    }
}
