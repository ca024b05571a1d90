package org.kheperasim.sim.calibration;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.kheperasim.link.calibrate.RobotBase;
import org.kheperasim.link.protocol.dialect.Dialect;
import org.kheperasim.sim.engine.robot.RobotType;
import org.kheperasim.sim.engine.robot.RobotTypes;

/**
 * {@code calibrate} starts from the nominal numbers of the robot its dialect speaks for: they are the
 * bundled robot type's (the robot files hold them; robot-link cannot read them, so this keeps the two
 * the same), and the robot it cannot measure is refused with what it lacks.
 */
class RobotBaseTest {
    @Test
    void theNominalNumbersAreTheRobotTypes() {
        for (String name : new String[] {"khepera1", "khepera2"}) {
            RobotBase b = RobotBase.of(Dialect.named(name));
            RobotType t = RobotTypes.named(name);
            assertEquals(t.name(), b.name());
            assertEquals(t.sensorCount(), b.sensors(), name + " sensors");
            assertEquals(t.proximity().maxReading(), b.fullScale(), name + " full scale");
            assertEquals(t.drive().mmPerPulse(), b.mmPerPulse(), name + " mm per pulse");
            assertEquals(t.drive().wheelBaseMm(), b.wheelBaseMm(), name + " wheel base");
        }
        assertEquals(2081, RobotBase.KHEPERA1.turnPulses(), "one nominal turn, as the procedure always spun");
    }

    @Test
    void theEpuckIsRefusedNamingWhatTheProcedureLacks() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> RobotBase.of(Dialect.named("epuck")));
        assertTrue(e.getMessage().contains("position commands") && e.getMessage().contains("12 bits")
                && e.getMessage().contains("0.1288 mm"), e.getMessage());
    }
}
