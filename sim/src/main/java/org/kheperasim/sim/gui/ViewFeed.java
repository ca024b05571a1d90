package org.kheperasim.sim.gui;

import java.util.ArrayList;
import java.util.List;
import org.kheperasim.sim.engine.view.RobotView;
import org.kheperasim.sim.engine.view.Snapshot;
import org.kheperasim.sim.replay.RobotSeries;

/**
 * The one source the window's panels show. The live run is the default; serving and replaying put
 * their own source in front while they last ({@link #show}, {@link #back}).
 */
final class ViewFeed {
    private final SnapshotSource live;
    private SnapshotSource shown;
    private final RobotSelection selection;

    /** @param live the window's run, shown when nothing else is @param selection the selected robot */
    ViewFeed(SnapshotSource live, RobotSelection selection) {
        this.live = live;
        this.shown = live;
        this.selection = selection;
    }

    /** @param source what to show from now on */
    void show(SnapshotSource source) {
        shown = source;
    }

    /** @param source stop showing it, if it is shown: back to the live run */
    void back(SnapshotSource source) {
        if (shown == source) {
            shown = live;
        }
    }

    /** @return what is shown */
    SnapshotSource source() {
        return shown;
    }

    Snapshot snapshot() {
        return shown.snapshot();
    }

    String state() {
        return shown.state();
    }

    /** @return the selected robot now, or null */
    RobotView selected() {
        return selection.in(shown.snapshot());
    }

    /** @return the image the selected robot's vision turret last gave its controller, or null */
    org.kheperasim.sim.engine.view.VisionView selectedVision() {
        Snapshot s = shown.snapshot();
        return s == null ? null : s.vision(selection.index()).orElse(null);
    }

    /** @return the selected robot's samples, or null */
    RobotSeries selectedSeries() {
        return shown.series(selection.index());
    }

    /** @return every robot's trail */
    List<float[]> trails() {
        Snapshot s = shown.snapshot();
        List<float[]> out = new ArrayList<>();
        if (s != null) {
            for (int i = 0; i < s.robots().size(); i++) {
                out.add(shown.trail(i));
            }
        }
        return out;
    }
}
