package org.kheperasim.sim.host.loading;

import java.io.PrintStream;
import java.util.logging.Formatter;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import java.util.logging.SimpleFormatter;
import org.kheperasim.sim.host.ControllerOutput;

/**
 * What the controller class loader puts in place of the calls of contained controller code that
 * would print to the JVM's own error stream or share state with the whole JVM: a stack trace
 * printed with {@code printStackTrace()}, and {@code Logger.getLogger(name)}. Both print to the
 * run's console ({@link ControllerOutput#err()}), each line stamped with its simulated time.
 */
public final class ConsoleHooks {
    /** Prints a record as {@code LEVEL: message}, and its exception's stack trace: no wall-clock time. */
    private static final Handler CONSOLE = new Handler() {
        private final Formatter messages = new SimpleFormatter();

        @Override
        public void publish(LogRecord record) {
            if (!isLoggable(record)) {
                return;
            }
            PrintStream err = ControllerOutput.err();
            err.println(record.getLevel().getName() + ": " + messages.formatMessage(record));
            if (record.getThrown() != null) {
                record.getThrown().printStackTrace(err);
            }
        }

        @Override
        public void flush() {
            ControllerOutput.err().flush();
        }

        @Override
        public void close() {
            // the console is the run's
        }
    };

    private ConsoleHooks() {
    }

    /** Replaces {@link Throwable#printStackTrace()}: the trace goes to the run's console, as errors. */
    public static void printStackTrace(Throwable t) {
        t.printStackTrace(ControllerOutput.err());
    }

    /**
     * Replaces {@link Logger#getLogger(String)}: a logger of the controller's own (not the JVM-wide
     * one of that name, which every robot and the simulator would share), at level INFO, that prints
     * to the run's console.
     *
     * @param name the name asked for; the logger is anonymous, so no other code can find it by name
     * @return a new logger
     */
    public static Logger getLogger(String name) {
        Logger logger = Logger.getAnonymousLogger();
        logger.setUseParentHandlers(false);
        logger.setLevel(Level.INFO);
        logger.addHandler(CONSOLE);
        return logger;
    }
}
