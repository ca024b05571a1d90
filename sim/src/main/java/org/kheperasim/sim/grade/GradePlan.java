package org.kheperasim.sim.grade;

import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Every run of a grading, in one fixed order (students by name, then arenas as given, then seeds
 * 1..N), and the deterministic slice of it that one shard makes: shard K of N makes the runs whose
 * index i (from 0) has {@code i % N == K - 1}, so the shards share the work evenly whatever the
 * order of slow and fast submissions, and together make every run once.
 *
 * @param students the student folders' names, sorted
 * @param arenas   the arenas as given
 * @param seeds    seeds 1..seeds
 */
public record GradePlan(List<String> students, List<String> arenas, int seeds) {

    private static final Pattern SHARD = Pattern.compile("(\\d{1,6})/(\\d{1,6})");

    /**
     * One run.
     *
     * @param index   its place in the whole grading, from 0
     * @param student the student
     * @param arena   the arena
     * @param seed    the seed
     */
    public record Job(int index, String student, String arena, long seed) {
    }

    /**
     * A slice of the grading.
     *
     * @param k this shard, 1..n
     * @param n how many shards
     */
    public record Shard(int k, int n) {
        /** The whole grading as one shard. */
        public static final Shard ALL = new Shard(1, 1);

        /** Checks 1 ≤ k ≤ n. */
        public Shard {
            if (n < 1 || k < 1 || k > n) {
                throw new IllegalArgumentException("--shard " + k + "/" + n
                        + ": give K/N with 1 <= K <= N, e.g. --shard 1/4");
            }
        }

        /**
         * @param text {@code K/N}
         * @return the shard
         */
        public static Shard parse(String text) {
            Matcher m = SHARD.matcher(text.strip());
            if (!m.matches()) {
                throw new IllegalArgumentException("--shard '" + text
                        + "': give K/N, this shard's number from 1 and the"
                        + " number of shards, e.g. --shard 2/8 (Slurm: --shard"
                        + " $((SLURM_ARRAY_TASK_ID+1))/$SLURM_ARRAY_TASK_COUNT)");
            }
            return new Shard(Integer.parseInt(m.group(1)), Integer.parseInt(m.group(2)));
        }

        @Override
        public String toString() {
            return k + "/" + n;
        }
    }

    /** Copies the lists and checks them. */
    public GradePlan {
        students = List.copyOf(students);
        arenas = List.copyOf(arenas);
        if (seeds < 1) {
            throw new IllegalArgumentException("--seeds " + seeds + ": give at least 1 (seeds 1..N are run)");
        }
        if (arenas.isEmpty()) {
            throw new IllegalArgumentException("no arena given; give --arenas maze two-rooms ...");
        }
    }

    /** @return every run, in order */
    public List<Job> jobs() {
        List<Job> out = new ArrayList<>();
        for (String s : students) {
            for (String a : arenas) {
                for (int seed = 1; seed <= seeds; seed++) {
                    out.add(new Job(out.size(), s, a, seed));
                }
            }
        }
        return out;
    }

    /** @param shard a slice @return its runs, in order */
    public List<Job> shard(Shard shard) {
        return jobs().stream().filter(j -> j.index() % shard.n() == shard.k() - 1).toList();
    }
}
