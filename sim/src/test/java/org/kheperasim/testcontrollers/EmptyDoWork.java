package org.kheperasim.testcontrollers;

import org.kheperasim.api.Controller;

/** A student's first file before they wrote anything: doWork() is empty. */
public class EmptyDoWork extends Controller {
    @Override
    protected void doWork() {
    }
}
