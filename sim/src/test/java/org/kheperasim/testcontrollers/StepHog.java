package org.kheperasim.testcontrollers;

import java.util.ArrayList;
import java.util.List;
import org.kheperasim.api.StepController;

/** Keeps 2 MB more at every step, in a list it never empties (a careless student's log). */
public class StepHog extends StepController {
    private final List<long[]> kept = new ArrayList<>();

    @Override
    protected void step() {
        setSpeeds(2, 2);
        kept.add(new long[1 << 18]);
    }
}
