package org.kheperasim.api.binding;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.Proxy;
import org.junit.jupiter.api.Test;
import org.kheperasim.api.CurrentRobotState;
import org.kheperasim.api.MessagePasser;
import org.kheperasim.api.spi.ControllerException;
import org.kheperasim.api.spi.Mount;
import org.kheperasim.api.spi.RobotPort;
import org.kheperasim.api.spi.RobotPorts;

/** Controllers of another style reach the backends through a ControllerStyle found by ServiceLoader. */
class ControllerStyleTest {
    /** The marker of the test style's controllers. */
    public interface Marked {
    }

    public static class MarkedController implements Marked {
    }

    public static class NotMarked {
    }

    public abstract static class AbstractMarked implements Marked {
    }

    /** Registered in this module's test resources. */
    public static final class MarkedStyle implements ControllerStyle {
        static volatile RobotPort lastPort;

        @Override
        public String describe() {
            return "implements Marked";
        }

        @Override
        public boolean claims(Class<?> type) {
            return Marked.class.isAssignableFrom(type);
        }

        @Override
        public void check(Class<?> type) {
            if (type == AbstractMarked.class) {
                throw new ControllerException("AbstractMarked is abstract");
            }
        }

        @Override
        public Thread instantiate(Class<?> type, RobotPort port, MessagePasser messages) {
            lastPort = port;
            return new Thread(type.getSimpleName());
        }
    }

    private static RobotPort port() {
        return (RobotPort) Proxy.newProxyInstance(RobotPort.class.getClassLoader(), new Class<?>[] {RobotPort.class},
                (proxy, method, args) -> method.getName().equals("toString") ? "fake port"
                        : method.getName().equals("mount") ? new Mount("s" + args[0], 0, 0, 0)
                        : method.isDefault() ? java.lang.reflect.InvocationHandler.invokeDefault(proxy, method, args) : null);
    }

    @Test
    void aClaimedClassIsCheckedAndBuiltByItsStyleOverThePortBehindTheState() {
        Controllers.check(MarkedController.class);
        RobotPort port = port();
        Thread t = Controllers.instantiate(MarkedController.class, new CurrentRobotState(port), new MessagePasser(port));
        assertEquals("MarkedController", t.getName());
        assertSame(port, MarkedStyle.lastPort);
        assertSame(port, RobotPorts.of(new CurrentRobotState(port)));
    }

    @Test
    void theStylesRefusalIsTheBackendsRefusal() {
        ControllerException e = assertThrows(ControllerException.class, () -> Controllers.check(AbstractMarked.class));
        assertEquals("AbstractMarked is abstract", e.getMessage());
    }

    @Test
    void aClassOfNoStyleIsRefusedNamingEveryStyle() {
        ControllerException e = assertThrows(ControllerException.class, () -> Controllers.check(NotMarked.class));
        assertTrue(e.getMessage().contains("does not extend Thread") && e.getMessage().contains("or implements Marked"),
                e.getMessage());
    }

    @Test
    void onlyCurrentRobotStateInstallsThePortAccessor() {
        new CurrentRobotState(port());
        assertThrows(IllegalStateException.class, () -> RobotPorts.install(CurrentRobotState.class, s -> null));
    }
}
