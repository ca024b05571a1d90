import org.kheperasim.api.*;

/** A step controller: the simulator calls step() at a fixed period. */
public class Stepper extends StepController {
    @Override
    protected void step() {
        int front = Math.max(proximity(IrSensor.FRONT_LEFT), proximity(IrSensor.FRONT_RIGHT));
        if (front > 400) {
            setSpeeds(4, -4);
        } else {
            setSpeeds(5, 5);
        }
    }
}
