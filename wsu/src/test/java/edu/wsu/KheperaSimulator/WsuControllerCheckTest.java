package edu.wsu.KheperaSimulator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.kheperasim.api.CurrentRobotState;
import org.kheperasim.api.MessagePasser;
import org.kheperasim.api.spi.ControllerException;
import org.kheperasim.api.binding.Controllers;

/** Which classes the backends accept as WSU controllers, and what they say about the others. */
class WsuControllerCheckTest {
    private final FakePort port = new FakePort();

    public abstract static class Abstract extends RobotController {
    }

    public static class NeedsArguments extends RobotController {
        public NeedsArguments(int speed) {
        }

        @Override
        public void doWork() {
        }

        @Override
        public void close() {
        }
    }

    public static class OnlyTheInterface implements Controller {
        @Override
        public void doWork() {
        }

        @Override
        public void close() {
        }

        @Override
        public void run() {
        }
    }

    public static class Plain {
    }

    public static class ThrowsWhenBuilt extends RobotController {
        public ThrowsWhenBuilt() {
            throw new IllegalStateException("no robot here");
        }

        @Override
        public void doWork() {
        }

        @Override
        public void close() {
        }
    }

    private static String refusal(Class<?> type) {
        return assertThrows(ControllerException.class, () -> Controllers.check(type)).getMessage();
    }

    @Test
    void aRobotControllerSubclassIsAController() {
        Controllers.check(Probe.class);
        Thread t = Controllers.instantiate(Probe.class, new CurrentRobotState(port), new MessagePasser(port));
        assertEquals("Probe", t.getName());
        assertEquals(Thread.State.NEW, t.getState());
    }

    @Test
    void unusableClassesAreRefusedWithTheFix() {
        String m = refusal(Abstract.class);
        assertTrue(m.contains("is abstract"), m);
        m = refusal(NeedsArguments.class);
        assertTrue(m.contains("no constructor without parameters") && m.contains("public NeedsArguments() { }"), m);
        m = refusal(OnlyTheInterface.class);
        assertTrue(m.contains("does not extend edu.wsu.KheperaSimulator.RobotController")
                && m.contains("extends RobotController"), m);
    }

    @Test
    void aClassOfNoStyleNamesEveryStyleIncludingWsu() {
        String m = refusal(Plain.class);
        assertTrue(m.contains("does not extend Thread") && m.contains("org.kheperasim.api.Controller")
                && m.contains("extends edu.wsu.KheperaSimulator.RobotController"), m);
    }

    @Test
    void aConstructorThatThrowsIsReportedWithItsCause() {
        ControllerException e = assertThrows(ControllerException.class, () -> Controllers.instantiate(
                ThrowsWhenBuilt.class, new CurrentRobotState(port), new MessagePasser(port)));
        assertTrue(e.getMessage().contains("constructor of controller") && e.getMessage().contains("no robot here"),
                e.getMessage());
        assertEquals("no robot here", e.getCause().getMessage());
    }
}
