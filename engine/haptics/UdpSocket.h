#pragma once
// A UDP/IPv4 socket for the bridge and its reference client: bind, send
// without blocking, receive with a timeout. Errors are sentences naming the
// address and the system's reason. send() and receive() allocate nothing, so
// the servo thread may send from its tick (see UdpBridgeDevice.h).

#include <cstddef>
#include <cstdint>
#include <string>

namespace hemiroll::haptics {

// An IPv4 address and port in host byte order (trivially copyable, so it can
// cross threads in a TripleBuffer).
struct UdpEndpoint {
  std::uint32_t address = 0;  // e.g. 0x7F000001 for 127.0.0.1
  std::uint16_t port = 0;
  bool operator==(const UdpEndpoint&) const = default;
};

// Parses dotted IPv4 ("127.0.0.1"); false when it is not one.
bool parseIpv4(const std::string& text, std::uint32_t& address);
std::string formatEndpoint(const UdpEndpoint& e);
inline bool isLoopback(std::uint32_t address) { return (address >> 24) == 127; }

class UdpSocket {
 public:
  UdpSocket() = default;
  ~UdpSocket() { close(); }
  UdpSocket(const UdpSocket&) = delete;
  UdpSocket& operator=(const UdpSocket&) = delete;

  // Binds to address:port (port 0 picks a free one, see localPort()).
  // Empty string on success, else why not.
  std::string bind(const UdpEndpoint& local);
  void close();
  bool isOpen() const { return fd_ >= 0; }
  std::uint16_t localPort() const { return localPort_; }

  // Non-blocking send; false when the kernel refused it (buffer full, no
  // route). Never waits.
  bool send(const std::uint8_t* data, std::size_t length, const UdpEndpoint& to) const;
  // Waits at most timeoutNs for one datagram; its length (a longer datagram
  // than capacity reports capacity + 1, so callers can reject it), 0 on
  // timeout, or -1 on an error.
  long receive(std::uint8_t* buffer, std::size_t capacity, UdpEndpoint& from, std::int64_t timeoutNs) const;

 private:
  int fd_ = -1;
  std::uint16_t localPort_ = 0;
};

}  // namespace hemiroll::haptics
