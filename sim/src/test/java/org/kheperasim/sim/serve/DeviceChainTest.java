package org.kheperasim.sim.serve;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.io.InputStream;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.kheperasim.api.spi.RobotPort;
import org.kheperasim.link.protocol.Command;
import org.kheperasim.link.protocol.dialect.Dialect;
import org.kheperasim.link.robot.RobotBackend;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.robot.Device;
import org.kheperasim.sim.engine.robot.RobotType;
import org.kheperasim.sim.engine.robot.RobotTypes;
import org.kheperasim.sim.engine.view.GripperView;
import org.kheperasim.sim.engine.view.RobotView;
import org.kheperasim.sim.engine.view.VisionView;
import org.kheperasim.sim.gui.VisionStrip;
import org.kheperasim.sim.trace.TraceWriter;
import org.objectweb.asm.ClassReader;
import org.objectweb.asm.ClassVisitor;
import org.objectweb.asm.MethodVisitor;
import org.objectweb.asm.Opcodes;

/**
 * Every device of {@link Device} has its whole chain (docs/adding-a-device.md): a command of the
 * Khepera's protocol that the protocol server answers; a column or line of the trace; a
 * method of the robot port that both the simulator and robot-link implement; and a panel of the
 * window that reads the device's state from the snapshot. A device added to the list without one
 * of these fails here, naming the link that is missing.
 */
class DeviceChainTest {

    /**
     * One device's chain.
     *
     * @param command a command line of the khepera1 dialect that reaches it
     * @param traceText text the trace writer writes for it (a column name or a line's start)
     * @param portMethod the robot port method a controller reaches it by
     * @param panel the window class that shows it
     * @param viewOwner the snapshot type the panel reads it from
     * @param viewMethod the accessor the panel calls on it
     */
    record Chain(String command, String traceText, String portMethod, String panel,
            Class<?> viewOwner, String viewMethod) {
    }

    private static final Map<Device, Chain> CHAINS = new EnumMap<>(Device.class);

    static {
        CHAINS.put(Device.PROXIMITY, new Chain("N", "prox0", "proximity", "org.kheperasim.sim.gui.SensorRenderer",
                RobotView.class, "proximity"));
        CHAINS.put(Device.AMBIENT_LIGHT, new Chain("O", "light0", "ambientLight", "org.kheperasim.sim.gui.SensorRenderer",
                RobotView.class, "light"));
        CHAINS.put(Device.WHEEL_SPEEDS, new Chain("D,3,-3", "speed_l", "setSpeeds", "org.kheperasim.sim.gui.SensorRenderer",
                RobotView.class, "speedLeft"));
        CHAINS.put(Device.WHEEL_POSITIONS, new Chain("H", "enc_l", "leftPosition", "org.kheperasim.sim.gui.SensorRenderer",
                RobotView.class, "encoderLeft"));
        CHAINS.put(Device.GRIPPER, new Chain("T,1,E,100", "fingers", "setArmDown", "org.kheperasim.sim.gui.SensorRenderer",
                GripperView.class, "armPosition"));
        CHAINS.put(Device.VISION, new Chain("T,2,N", "# vision", "visionImage", "org.kheperasim.sim.gui.VisionStrip",
                VisionView.class, "pixels"));
    }

    @Test
    void everyDeviceHasItsProtocolCommandTraceColumnPortMethodAndPanel() throws Exception {
        List<String> gaps = new ArrayList<>();
        Dialect khepera = Dialect.named(Dialect.DEFAULT);
        Set<String> traceStrings = strings(TraceWriter.class);
        Class<?> simulatedPort = Class.forName("org.kheperasim.sim.host.SimulatedRobotPort");
        try (Served served = new Served("", Settings.defaults(), 1); LineClient client = served.client()) {
            for (Device d : Device.values()) {
                Chain c = CHAINS.get(d);
                if (c == null) {
                    gaps.add(d + ": no chain listed here; follow docs/adding-a-device.md and add it to CHAINS");
                    continue;
                }
                try {
                    Command command = khepera.parseCommand(c.command());
                    String reply = client.ask(c.command());
                    khepera.parseReply(command, reply); // throws for an error reply or one that answers something else
                } catch (RuntimeException e) {
                    gaps.add(d + ": '" + c.command() + "' is not answered by the khepera1 dialect's server: " + e.getMessage());
                }
                if (traceStrings.stream().noneMatch(s -> s.contains(c.traceText()))) {
                    gaps.add(d + ": the trace writer writes no '" + c.traceText() + "'");
                }
                for (Class<?> port : List.of(RobotPort.class, simulatedPort, RobotBackend.class)) {
                    if (!declares(port, c.portMethod())) {
                        gaps.add(d + ": " + port.getSimpleName() + " has no method " + c.portMethod());
                    }
                }
                String owner = c.viewOwner().getName().replace('.', '/');
                if (!calls(Class.forName(c.panel())).contains(owner + "." + c.viewMethod())) {
                    gaps.add(d + ": the panel " + c.panel() + " never reads " + c.viewOwner().getSimpleName()
                            + "." + c.viewMethod() + "()");
                }
            }
        }
        assertEquals(List.of(), gaps, "devices whose chain has a gap (docs/adding-a-device.md)");
    }

    @Test
    void aRobotHasTheDevicesOfItsFile() {
        assertEquals(Set.of(Device.PROXIMITY, Device.AMBIENT_LIGHT, Device.WHEEL_SPEEDS, Device.WHEEL_POSITIONS,
                Device.GRIPPER, Device.VISION), Device.of(RobotTypes.KHEPERA1));
        RobotType epuck = RobotTypes.resolve("epuck", null);
        assertTrue(!Device.of(epuck).contains(Device.GRIPPER) && !Device.of(epuck).contains(Device.VISION),
                "the e-puck carries no Khepera turret: " + Device.of(epuck));
    }

    @Test
    void theChainCheckSeesAMissingLink() throws Exception {
        // The check itself: a panel that reads no vision image, and a port without a method, are reported.
        assertTrue(!calls(VisionStrip.class).contains("org/kheperasim/sim/engine/view/RobotView.encoderLeft"));
        assertTrue(!declares(RobotPort.class, "noSuchDevice"));
        assertTrue(strings(TraceWriter.class).stream().noneMatch(s -> s.contains("no_such_column")));
    }

    private static boolean declares(Class<?> type, String method) {
        for (Class<?> c = type; c != null; c = c.getSuperclass()) {
            for (java.lang.reflect.Method m : c.getDeclaredMethods()) {
                if (m.getName().equals(method) && !m.isSynthetic()) {
                    return true;
                }
            }
        }
        return false;
    }

    private static ClassReader reader(Class<?> c) throws IOException {
        try (InputStream in = c.getResourceAsStream(c.getName().substring(c.getName().lastIndexOf('.') + 1) + ".class")) {
            if (in == null) {
                fail("no class file for " + c.getName());
            }
            return new ClassReader(in.readAllBytes());
        }
    }

    /** @return owner.name of every method the class (and its nested classes, by name) calls */
    private static Set<String> calls(Class<?> c) throws IOException {
        Set<String> out = new HashSet<>();
        List<Class<?>> all = new ArrayList<>(List.of(c));
        all.addAll(List.of(c.getDeclaredClasses()));
        for (Class<?> k : all) {
            reader(k).accept(new ClassVisitor(Opcodes.ASM9) {
                @Override
                public MethodVisitor visitMethod(int access, String name, String descriptor, String signature, String[] ex) {
                    return new MethodVisitor(Opcodes.ASM9) {
                        @Override
                        public void visitMethodInsn(int op, String owner, String method, String desc, boolean itf) {
                            out.add(owner + "." + method);
                        }
                    };
                }
            }, ClassReader.SKIP_DEBUG);
        }
        return out;
    }

    /** @return the string constants of the class */
    private static Set<String> strings(Class<?> c) throws IOException {
        Set<String> out = new HashSet<>();
        reader(c).accept(new ClassVisitor(Opcodes.ASM9) {
            @Override
            public MethodVisitor visitMethod(int access, String name, String descriptor, String signature, String[] ex) {
                return new MethodVisitor(Opcodes.ASM9) {
                    @Override
                    public void visitLdcInsn(Object value) {
                        if (value instanceof String s) {
                            out.add(s);
                        }
                    }
                };
            }
        }, ClassReader.SKIP_DEBUG);
        return out;
    }
}
