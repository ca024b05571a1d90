package util;

/** A moving average over the last n readings: the spike filter students wrote by hand. */
public class Smoother {
    private final int[] window;
    private int next;
    private int count;

    public Smoother(int n) {
        window = new int[n];
    }

    public int add(int value) {
        window[next] = value;
        next = (next + 1) % window.length;
        count = Math.min(count + 1, window.length);
        int sum = 0;
        for (int i = 0; i < count; i++) {
            sum += window[i];
        }
        return sum / count;
    }
}
