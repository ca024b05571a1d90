package org.kheperasim.link.cli;

import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.function.Supplier;
import org.kheperasim.link.protocol.Command;
import org.kheperasim.link.protocol.EpuckCommand;
import org.kheperasim.link.protocol.dialect.EpuckDialect;
import org.kheperasim.link.protocol.Reply;
import org.kheperasim.link.protocol.TurretCommand;
import org.kheperasim.link.session.Session;
import org.kheperasim.link.session.SessionException;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code check}: every command once, a table of results and round-trip times. */
@picocli.CommandLine.Command(name = "check", mixinStandardHelpOptions = true,
        description = "Send every protocol command once (the robot does not"
        + " move: C targets the current position, G keeps the counters, D and P are zero) and print a table.")
final class CheckCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Mixin
    Connection connection;

    @Option(names = "--bus-write", paramLabel = "DATA,ADDR", split = ",",
            description = "Also send W,DATA,ADDR (writes a byte on the extension bus; off unless given).")
    int[] busWrite;

    @Option(names = "--no-gripper", description = "Skip the gripper turret's commands (T,1,...).")
    boolean noGripper;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        try (Session session = connection.open(out)) {
            Session.Versions v = session.open();
            out.println(answers(session, v));
            Reply counters = session.exchange(session.dialect().readCounters());
            int l = counters.intValue(0);
            int r = counters.intValue(1);
            boolean epuck = session.dialect() == EpuckDialect.EPUCK;
            List<Supplier<Command>> plan = new ArrayList<>(epuck ? List.of(
                    EpuckCommand.Version::new,
                    () -> new EpuckCommand.SetSpeed(0, 0),
                    Command.ReadSpeed::new,
                    () -> new EpuckCommand.SetSteps(l, r),
                    EpuckCommand.ReadSteps::new,
                    () -> new EpuckCommand.SetLed(EpuckCommand.ALL_LEDS, 0),
                    () -> new EpuckCommand.BodyLed(0),
                    () -> new EpuckCommand.FrontLed(0),
                    Command.ReadProximity::new,
                    Command.ReadLight::new,
                    EpuckCommand.Stop::new) : List.of(
                    () -> new Command.SetSpeedPid(3800, 800, 100),
                    Command.ReadVersion::new,
                    () -> new Command.MoveToPosition(l, r),
                    () -> new Command.SetSpeed(0, 0),
                    Command.ReadSpeed::new,
                    () -> new Command.SetPositionPid(3000, 20, 4000),
                    () -> new Command.SetPositionCounters(l, r),
                    Command.ReadPositionCounters::new,
                    () -> new Command.ReadAnalog(0),
                    () -> new Command.SetPositionProfile(20, 64, 20, 64),
                    Command.ReadMotionStatus::new,
                    () -> new Command.SetLed(0, 0),
                    Command.ReadProximity::new,
                    Command.ReadLight::new,
                    () -> new Command.SetPwm(0, 0),
                    () -> new Command.ReadBus(0)));
            if (busWrite != null) {
                if (busWrite.length != 2) {
                    throw new IllegalArgumentException("--bus-write takes DATA,ADDR, e.g. --bus-write 0,0");
                }
                plan.add(() -> new Command.WriteBus(busWrite[0], busWrite[1]));
            }
            if (!noGripper && !epuck) {
                plan.add(() -> Command.Turret.gripper(new TurretCommand.Version()));
                plan.add(() -> Command.Turret.gripper(new TurretCommand.Barrier()));
                plan.add(() -> Command.Turret.gripper(new TurretCommand.Resistivity()));
                plan.add(() -> Command.Turret.gripper(new TurretCommand.MotorPosition(0)));
                plan.add(() -> Command.Turret.gripper(new TurretCommand.MotorPosition(1)));
                plan.add(() -> Command.Turret.gripper(new TurretCommand.Fingers(false)));
                plan.add(() -> Command.Turret.gripper(new TurretCommand.Arm(TurretCommand.ARM_UP)));
            }
            out.println(String.format(Locale.ROOT, "%-14s %-8s %-36s %9s", "command", "result", "reply", "rtt ms"));
            int failed = 0;
            boolean lost = false;
            for (Supplier<Command> next : plan) {
                Command c = next.get();
                long start = System.nanoTime();
                String result;
                String reply;
                try {
                    reply = session.exchange(c).encode();
                    result = "ok";
                } catch (SessionException e) {
                    failed++;
                    result = switch (e.kind()) {
                        case REFUSED -> "REFUSED";
                        case NO_REPLY -> "NO REPLY";
                        case LINK_LOST -> "LOST";
                    };
                    reply = e.getCause() instanceof org.kheperasim.link.protocol.ProtocolException p ? p.line() : "";
                    lost = e.kind() == SessionException.Kind.LINK_LOST;
                }
                out.println(String.format(Locale.ROOT, "%-14s %-8s %-36s %9.2f", c.encode(), result,
                        reply, (System.nanoTime() - start) / 1e6));
                out.flush();
                if (lost) {
                    break;
                }
            }
            Command stop = session.dialect().setSpeeds(0, 0);
            try {
                session.exchange(stop);
            } catch (SessionException e) {
                session.sendBlind(stop);
            }
            Session.Stats s = session.stats();
            out.println(String.format(Locale.ROOT,
                    "%d of %d commands answered; %d retries; the robot was left with D,0,0",
                    plan.size() - failed, plan.size(), s.retries()));
            out.flush();
            return failed == 0 ? 0 : 1;
        }
    }

    /**
     * @param session an open session
     * @param v what its version command answered
     * @return the line saying so: the Khepera's BIOS and protocol versions, the e-puck's version text
     */
    static String answers(Session session, Session.Versions v) {
        return session.dialect() == EpuckDialect.EPUCK ? "robot answers: " + v.bios() + " (e-puck)"
                : "robot answers: BIOS " + v.bios() + ", protocol " + v.protocol();
    }
}
