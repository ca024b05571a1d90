package org.kheperasim.sim.web;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.Region;
import org.kheperasim.sim.arena.Task;
import org.kheperasim.sim.task.RunFacts;
import org.kheperasim.sim.task.Score;

/**
 * The score as it stood at each sample of a run, by the task code every run is scored with
 * ({@link Score#of}): the facts at a moment are the regions entered by then (the run's own entry
 * times when its final facts are known, else the first sample with a robot's centre inside, as the
 * window's live score takes them) and the caps lying in each region at that sample. Floor coverage
 * is known only at the end, from the run's facts: until then a {@code cover} task is "pending".
 * At the last sample with the run's facts known, the score is exactly the run's.
 */
final class ScoreTimeline {
    /**
     * The score from {@code ms} on.
     *
     * @param ms      when it became this, ms
     * @param score   the score
     * @param pending true while a {@code cover} task's share is not known (counted as 0)
     */
    record Moment(long ms, Score score, boolean pending) {
    }

    private ScoreTimeline() {
    }

    /**
     * @param tape       the run
     * @param finalFacts what the run counted at its end, or null
     * @return the score at the first sample and at every sample where it changed; empty when the arena sets no task
     */
    static List<Moment> of(RunTape tape, RunFacts finalFacts) {
        List<Moment> out = new ArrayList<>();
        if (tape.robots().isEmpty() || !tape.arenas().get(0).arena().assignment().hasTasks()) {
            return out;
        }
        List<RunTape.Track> robots = tape.robots();
        RunTape.Track lead = robots.get(0);
        // The run's own entries in time order, when known; else the entries seen in the samples.
        List<Map.Entry<String, Double>> known = finalFacts == null ? List.of()
                : finalFacts.regionsEntered().entrySet().stream().sorted(Map.Entry.comparingByValue()).toList();
        int nextKnown = 0;
        Map<String, Double> entered = new LinkedHashMap<>();
        Map<Integer, int[]> caps = new HashMap<>();
        List<RunTape.CapMove> moves = tape.caps();
        int nextMove = 0;
        Arena shown = null;
        Map<String, Integer> capsIn = Map.of();
        for (int k = 0; k < lead.size(); k++) {
            long ms = lead.t.get(k);
            Arena arena = tape.arenaAt(ms);
            // The score changes only with the facts: most samples need no scoring.
            boolean changed = arena != shown;
            boolean capsMoved = changed;
            while (nextMove < moves.size() && moves.get(nextMove).ms() <= ms) {
                RunTape.CapMove m = moves.get(nextMove++);
                caps.put(m.cap(), new int[] {m.x10(), m.y10(), m.heldBy()});
                capsMoved = true;
            }
            if (capsMoved) {
                Map<String, Integer> now = capsIn(arena, caps);
                changed |= !now.equals(capsIn);
                capsIn = now;
            }
            if (finalFacts != null) {
                while (nextKnown < known.size() && known.get(nextKnown).getValue() * 1000 <= ms + 1e-6) {
                    Map.Entry<String, Double> e = known.get(nextKnown++);
                    entered.put(e.getKey(), e.getValue());
                    changed = true;
                }
            } else {
                changed |= enter(entered, arena, robots, k, ms);
            }
            boolean exact = k == lead.size() - 1 && finalFacts != null;
            if (!changed && !exact) {
                continue;
            }
            shown = arena;
            RunFacts facts = exact ? finalFacts : new RunFacts(ms / 1000.0, entered, 0, capsIn, arena.caps().size());
            boolean pending = !exact && arena.assignment().tasks().stream().anyMatch(t -> t instanceof Task.Cover);
            Score score = Score.of(arena, facts);
            if (out.isEmpty() || !same(out.get(out.size() - 1), score, pending)) {
                out.add(new Moment(ms, score, pending));
            }
        }
        return out;
    }

    private static boolean same(Moment m, Score s, boolean pending) {
        return m.pending() == pending && m.score().summary().equals(s.summary());
    }

    /**
     * Regions some robot's centre lies in at sample {@code k}, entered now unless entered before. @return true when one
     * was
     */
    private static boolean enter(Map<String, Double> entered, Arena arena, List<RunTape.Track> robots, int k, long ms) {
        boolean any = false;
        for (RunTape.Track r : robots) {
            int i = StrictMath.min(k, r.size() - 1);
            double x = r.x.get(i) / 10.0;
            double y = r.y.get(i) / 10.0;
            for (Region g : arena.regions()) {
                if (g.contains(x, y) && !entered.containsKey(g.name())) {
                    entered.put(g.name(), ms / 1000.0);
                    any = true;
                }
            }
        }
        return any;
    }

    private static Map<String, Integer> capsIn(Arena arena, Map<Integer, int[]> caps) {
        Map<String, Integer> in = new LinkedHashMap<>();
        for (Region g : arena.regions()) {
            int n = 0;
            for (int[] c : caps.values()) {
                if (c[2] < 0 && g.contains(c[0] / 10.0, c[1] / 10.0)) {
                    n++;
                }
            }
            in.put(g.name(), n);
        }
        return in;
    }
}
