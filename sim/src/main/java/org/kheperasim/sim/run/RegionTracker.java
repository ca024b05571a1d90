package org.kheperasim.sim.run;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.kheperasim.sim.arena.Region;
import org.kheperasim.sim.engine.RobotView;
import org.kheperasim.sim.engine.Snapshot;
import org.kheperasim.sim.engine.SnapshotListener;

/** Records when each robot's centre first entered each named region of the arena. */
final class RegionTracker implements SnapshotListener {
    private final List<Region> regions;
    private final List<Map<String, Double>> entered;

    RegionTracker(List<Region> regions, int robots) {
        this.regions = regions;
        this.entered = new java.util.ArrayList<>();
        for (int i = 0; i < robots; i++) {
            entered.add(new LinkedHashMap<>());
        }
    }

    @Override
    public void onSnapshot(Snapshot snapshot) {
        for (RobotView r : snapshot.robots()) {
            Map<String, Double> seen = entered.get(r.id());
            if (seen.size() == regions.size()) {
                continue;
            }
            for (Region region : regions) {
                if (!seen.containsKey(region.name()) && region.contains(r.x(), r.y())) {
                    seen.put(region.name(), snapshot.timeSeconds());
                }
            }
        }
    }

    /** @return for robot {@code i}, the regions entered and when, in arena order */
    Map<String, Double> entered(int i) {
        Map<String, Double> ordered = new LinkedHashMap<>();
        for (Region region : regions) {
            Double t = entered.get(i).get(region.name());
            if (t != null) {
                ordered.put(region.name(), t);
            }
        }
        return ordered;
    }
}
