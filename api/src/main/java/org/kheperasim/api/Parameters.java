package org.kheperasim.api;

import java.util.Arrays;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Set;

/**
 * Numbers a run hands its controller: a weight vector, a genome, a gain. An evolutionary algorithm or
 * a learning loop (in any language, through {@code khepera-sim evaluate}) runs the same controller
 * class with other parameters, and the controller reads them with {@link Controller#parameters()} or
 * {@link StepController#parameters()}:
 * <pre>{@code
 * double[] w = parameters().vector("weights", DEFAULT_WEIGHTS);
 * double gain = parameters().get("gain", 1.0);
 * }</pre>
 * Each parameter is a name and one or more numbers; a run without parameters has none, so every
 * lookup gives its default. Immutable.
 */
public final class Parameters {
    /** No parameters: every lookup gives its default. */
    public static final Parameters NONE = new Parameters(Map.of());

    private final Map<String, double[]> values;

    private Parameters(Map<String, double[]> values) {
        this.values = values;
    }

    /**
     * @param values each parameter's name and numbers (copied)
     * @return the parameters
     * @throws IllegalArgumentException for an empty name, no numbers, or a number that is not finite
     */
    public static Parameters of(Map<String, double[]> values) {
        Map<String, double[]> copy = new LinkedHashMap<>();
        for (Map.Entry<String, double[]> e : values.entrySet()) {
            if (e.getKey() == null || e.getKey().isBlank()) {
                throw new IllegalArgumentException("a parameter needs a name");
            }
            if (e.getValue() == null || e.getValue().length == 0) {
                throw new IllegalArgumentException("parameter " + e.getKey() + " has no numbers");
            }
            for (double v : e.getValue()) {
                if (!Double.isFinite(v)) {
                    throw new IllegalArgumentException("parameter " + e.getKey() + " holds " + v
                            + ": numbers must be finite");
                }
            }
            copy.put(e.getKey(), e.getValue().clone());
        }
        return copy.isEmpty() ? NONE : new Parameters(Collections.unmodifiableMap(copy));
    }

    /** @return the parameters' names, in the order given */
    public Set<String> names() {
        return values.keySet();
    }

    /** @return true when there are none */
    public boolean isEmpty() {
        return values.isEmpty();
    }

    /**
     * @param name a parameter's name
     * @param otherwise what to give when the run has no such parameter
     * @return its (first) number, or {@code otherwise}
     */
    public double get(String name, double otherwise) {
        double[] v = values.get(name);
        return v == null ? otherwise : v[0];
    }

    /**
     * @param name a parameter's name
     * @param otherwise what to give when the run has no such parameter
     * @return a copy of its numbers, or of {@code otherwise}
     */
    public double[] vector(String name, double[] otherwise) {
        double[] v = values.get(name);
        return (v == null ? otherwise : v).clone();
    }

    /** @return e.g. {@code gain=2.5 weights=0.4,0.8,-1.2}: the form a trace header and the console show */
    @Override
    public String toString() {
        StringBuilder sb = new StringBuilder();
        for (Map.Entry<String, double[]> e : values.entrySet()) {
            if (sb.length() > 0) {
                sb.append(' ');
            }
            sb.append(e.getKey()).append('=');
            double[] v = e.getValue();
            for (int i = 0; i < v.length; i++) {
                sb.append(i == 0 ? "" : ",").append(Double.toString(v[i]));
            }
        }
        return sb.toString();
    }

    @Override
    public boolean equals(Object o) {
        if (!(o instanceof Parameters p) || !p.values.keySet().equals(values.keySet())) {
            return false;
        }
        for (Map.Entry<String, double[]> e : values.entrySet()) {
            if (!Arrays.equals(e.getValue(), p.values.get(e.getKey()))) {
                return false;
            }
        }
        return true;
    }

    @Override
    public int hashCode() {
        int h = 0;
        for (Map.Entry<String, double[]> e : values.entrySet()) {
            h += e.getKey().hashCode() ^ Arrays.hashCode(e.getValue());
        }
        return h;
    }
}
