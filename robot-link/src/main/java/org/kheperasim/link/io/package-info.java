/**
 * Line-shaped links to a robot: {@link org.kheperasim.link.io.Link} with implementations over a
 * serial port ({@link org.kheperasim.link.io.SerialLink}, the only class that touches jSerialComm),
 * over TCP ({@link org.kheperasim.link.io.TcpLink}) and in memory ({@link org.kheperasim.link.io.MemoryLink}).
 */
package org.kheperasim.link.io;
